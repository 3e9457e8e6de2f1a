package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.AcceptableOrderTypeDto
import org.ktcs.kernel.web.v1.BoundingBoxDto
import org.ktcs.kernel.web.v1.NanAsStringSerializer
import org.ktcs.kernel.web.v1.PropertyDto
import org.ktcs.kernel.web.v1.TripleDto
import org.ktcs.kernel.web.v1.orders.DestinationStateDto
import org.ktcs.kernel.web.v1.orders.toDestinationState
import org.ktcs.kernel.web.v1.toDto
import org.ktcs.kernel.web.v1.toPropertyDtos
import org.ktcs.kernel.web.v1.toWire
import org.ktcs.kernel.web.v1.vehicles.toDto
import java.time.Instant

/** The answer of `GET /events`: the status messages in the requested sequence number range. */
@Serializable
data class GetEventsResponse(val timeStamp: String, val statusMessages: List<StatusMessage>)

/** One entry of `GET /events`; `type` (`TransportOrder`, `Vehicle`) says which kind it is. */
@Serializable
sealed interface StatusMessage {
    val sequenceNumber: Long
    val creationTimeStamp: String
}

@Serializable
@SerialName("TransportOrder")
data class OrderStatusMessage(
    override val sequenceNumber: Long,
    override val creationTimeStamp: String,
    val orderName: String,
    val dispensable: Boolean,
    val peripheralReservationToken: String?,
    val wrappingSequence: String?,
    val orderType: String,
    val intendedVehicle: String?,
    val processingVehicleName: String?,
    val orderState: String,
    val destinations: List<DestinationStateDto>,
    val properties: List<PropertyDto>,
) : StatusMessage

@Serializable
@SerialName("Vehicle")
data class VehicleStatusMessage(
    override val sequenceNumber: Long,
    override val creationTimeStamp: String,
    val vehicleName: String,
    val properties: List<PropertyDto>,
    val transportOrderName: String?,
    val boundingBox: BoundingBoxDto,
    val energyLevelGood: Int,
    val energyLevelCritical: Int,
    val energyLevelSufficientlyRecharged: Int,
    val energyLevelFullyRecharged: Int,
    val energyLevel: Int,
    val integrationLevel: String,
    val position: String?,
    val precisePosition: TripleDto?,
    @Serializable(with = NanAsStringSerializer::class) val orientationAngle: Double,
    val paused: Boolean,
    val state: String,
    val stateTimestamp: String,
    val procState: String,
    val procStateTimestamp: String,
    val allocatedResources: List<List<String>>,
    val claimedResources: List<List<String>>,
    val acceptableOrderTypes: List<AcceptableOrderTypeDto>,
    val envelopeKey: String?,
) : StatusMessage

fun TransportOrder.toStatusMessage(sequenceNumber: Long, createdAt: Instant): OrderStatusMessage = OrderStatusMessage(
    sequenceNumber = sequenceNumber,
    creationTimeStamp = createdAt.toWire(),
    orderName = name,
    dispensable = dispensable,
    peripheralReservationToken = peripheralReservationToken,
    wrappingSequence = wrappingSequence,
    orderType = type,
    intendedVehicle = intendedVehicle,
    processingVehicleName = processingVehicle,
    orderState = state.name,
    destinations = driveOrders.map { it.toDestinationState() },
    properties = properties.toPropertyDtos(),
)

fun Vehicle.toStatusMessage(sequenceNumber: Long, createdAt: Instant): VehicleStatusMessage = VehicleStatusMessage(
    sequenceNumber = sequenceNumber,
    creationTimeStamp = createdAt.toWire(),
    vehicleName = name,
    properties = properties.toPropertyDtos(),
    transportOrderName = transportOrder,
    boundingBox = boundingBox.toDto(),
    energyLevelGood = energyLevelThresholdSet.good,
    energyLevelCritical = energyLevelThresholdSet.critical,
    energyLevelSufficientlyRecharged = energyLevelThresholdSet.sufficientlyRecharged,
    energyLevelFullyRecharged = energyLevelThresholdSet.fullyRecharged,
    energyLevel = energyLevel,
    integrationLevel = integrationLevel.name,
    position = currentPosition,
    precisePosition = precisePosition?.toDto(),
    orientationAngle = orientationAngle,
    paused = paused,
    state = state.name,
    stateTimestamp = stateTimestamp.toWire(),
    procState = procState.name,
    procStateTimestamp = procStateTimestamp.toWire(),
    allocatedResources = allocatedResources.map { it.toList() },
    claimedResources = claimedResources.map { it.toList() },
    acceptableOrderTypes = acceptableOrderTypes.map { it.toDto() },
    envelopeKey = envelopeKey,
)
