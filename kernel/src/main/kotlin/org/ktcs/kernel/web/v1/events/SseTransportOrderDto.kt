package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.orders.waitingReason
import org.ktcs.kernel.web.v1.ObjectHistoryDto
import org.ktcs.kernel.web.v1.orders.RouteDto
import org.ktcs.kernel.web.v1.orders.orMaxInstant
import org.ktcs.kernel.web.v1.toDto
import org.ktcs.kernel.web.v1.toWire

/** A transport order in an SSE event. Here v1 writes properties as a JSON object and lists no destination states. */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
data class SseTransportOrderDto(
    val name: String,
    val properties: Map<String, String>,
    val history: ObjectHistoryDto,
    val type: String,
    val dependencies: List<String>,
    val driveOrders: List<SseDriveOrderDto>,
    val peripheralReservationToken: String?,
    val currentDriveOrderIndex: Int,
    val currentRouteStepIndex: Int,
    val state: String,
    val creationTime: String,
    val deadline: String,
    val finishedTime: String,
    val intendedVehicle: String?,
    val processingVehicle: String?,
    val wrappingSequence: String?,
    val dispensable: Boolean,
    /** kTCS only (see [waitingReason]); left out of the JSON when `null`, so openTCS clients see v1's fields. */
    @EncodeDefault(EncodeDefault.Mode.NEVER)
    val waitingReason: String? = null,
)

@Serializable
data class SseDriveOrderDto(
    val name: String,
    val destination: SseDestinationDto,
    val transportOrder: String,
    /** The JSON of [RouteDto] or `null`, encoded once per route (see [EncodedRoutes]). */
    val route: JsonElement,
    val state: String,
)

@Serializable
data class SseDestinationDto(val destination: String, val operation: String, val properties: Map<String, String>)

/**
 * The WebSocket stream writes the same JSON without this DTO (`ws/OrderJsonWriter.kt`); its test compares the two
 * byte for byte, so a field added here fails it until the writer writes it too.
 */
fun TransportOrder.toSseDto(): SseTransportOrderDto = SseTransportOrderDto(
    name = name,
    properties = properties,
    history = history.toDto(),
    type = type,
    dependencies = dependencies.toList(),
    driveOrders = driveOrders.map { it.toSseDto(name) },
    peripheralReservationToken = peripheralReservationToken,
    currentDriveOrderIndex = currentDriveOrderIndex,
    currentRouteStepIndex = currentRouteStepIndex,
    state = state.name,
    creationTime = creationTime.toWire(),
    deadline = deadline.toWire(),
    finishedTime = finishedTime.orMaxInstant(),
    intendedVehicle = intendedVehicle,
    processingVehicle = processingVehicle,
    wrappingSequence = wrappingSequence,
    dispensable = dispensable,
    waitingReason = waitingReason(),
)

private fun DriveOrder.toSseDto(order: String) = SseDriveOrderDto(
    name = name,
    destination = SseDestinationDto(destination.target, destination.operation, destination.properties),
    transportOrder = order,
    route = EncodedRoutes.of("$order/$name", route),
    state = state.name,
)
