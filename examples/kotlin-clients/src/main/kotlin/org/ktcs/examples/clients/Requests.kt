package org.ktcs.examples.clients

import kotlinx.serialization.Serializable

/** The body of `POST /v1/transportOrders/{name}` (openTCS web API v1). */
@Serializable
data class TransportOrderRequest(
    val destinations: List<DestinationRequest>,
    val intendedVehicle: String? = null,
    val wrappingSequence: String? = null,
)

/** A destination: a location and an operation it allows, or a point with "MOVE" (or "PARK" at a park position). */
@Serializable
data class DestinationRequest(val locationName: String, val operation: String)

/** The body of `POST /v1/orderSequences/{name}`. */
@Serializable
data class OrderSequenceRequest(val intendedVehicle: String? = null, val failureFatal: Boolean = false)

/** What the examples read of a transport order; the web API sends more, which is ignored. */
@Serializable
data class TransportOrderView(
    val name: String,
    val state: String,
    val processingVehicle: String? = null,
    val wrappingSequence: String? = null,
)

/** What the examples read of a vehicle. */
@Serializable
data class VehicleView(val name: String, val currentPosition: String? = null, val procState: String)

/** The subscription a WebSocket client sends first; `type` is always "subscribe". */
@Serializable
data class Subscription(val type: String, val topics: List<String>)
