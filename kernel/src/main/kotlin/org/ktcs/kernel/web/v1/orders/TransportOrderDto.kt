package org.ktcs.kernel.web.v1.orders

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.orders.waitingReason
import org.ktcs.kernel.web.v1.ObjectHistoryDto
import org.ktcs.kernel.web.v1.PropertyDto
import org.ktcs.kernel.web.v1.toDto
import org.ktcs.kernel.web.v1.toPropertyDtos
import org.ktcs.kernel.web.v1.toWire
import java.time.Instant

/** A transport order as `GET /transportOrders/{NAME}` answers it. */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
data class TransportOrderDto(
    val dispensable: Boolean,
    val name: String,
    val history: ObjectHistoryDto,
    val dependencies: List<String>,
    val driveOrders: List<DriveOrderDto>,
    val currentDriveOrderIndex: Int,
    val currentRouteStepIndex: Int,
    val creationTime: String,
    val deadline: String,
    val finishedTime: String,
    val peripheralReservationToken: String?,
    val wrappingSequence: String?,
    val type: String,
    val state: String,
    val intendedVehicle: String?,
    val processingVehicle: String?,
    val destinations: List<DestinationStateDto>,
    val properties: List<PropertyDto>,
    /** kTCS only (see [waitingReason]); left out of the JSON when `null`, so openTCS clients see v1's fields. */
    @EncodeDefault(EncodeDefault.Mode.NEVER)
    val waitingReason: String? = null,
)

/** One destination's progress, as v1 lists them beside the full drive orders. */
@Serializable
data class DestinationStateDto(
    val locationName: String,
    val operation: String,
    val state: String,
    val properties: List<PropertyDto>,
)

@Serializable
data class DriveOrderDto(
    val name: String,
    val destination: DriveOrderDestinationDto,
    val transportOrder: String,
    val route: RouteDto?,
    val state: String,
)

@Serializable
data class DriveOrderDestinationDto(val destination: String, val operation: String, val properties: List<PropertyDto>)

/** openTCS writes "not finished yet" as the largest instant; kTCS keeps it as `null`. */
fun Instant?.orMaxInstant(): String = (this ?: Instant.MAX).toWire()

fun TransportOrder.toDto(): TransportOrderDto = TransportOrderDto(
    dispensable = dispensable,
    name = name,
    history = history.toDto(),
    dependencies = dependencies.toList(),
    driveOrders = driveOrders.map { it.toDto(name) },
    currentDriveOrderIndex = currentDriveOrderIndex,
    currentRouteStepIndex = currentRouteStepIndex,
    creationTime = creationTime.toWire(),
    deadline = deadline.toWire(),
    finishedTime = finishedTime.orMaxInstant(),
    peripheralReservationToken = peripheralReservationToken,
    wrappingSequence = wrappingSequence,
    type = type,
    state = state.name,
    intendedVehicle = intendedVehicle,
    processingVehicle = processingVehicle,
    destinations = driveOrders.map { it.toDestinationState() },
    properties = properties.toPropertyDtos(),
    waitingReason = waitingReason(),
)

fun DriveOrder.toDestinationState(): DestinationStateDto =
    DestinationStateDto(destination.target, destination.operation, state.name, destination.properties.toPropertyDtos())

private fun DriveOrder.toDto(order: String) = DriveOrderDto(
    name = name,
    destination = destination.toDto(),
    transportOrder = order,
    route = route?.toDto(),
    state = state.name,
)

private fun Destination.toDto() = DriveOrderDestinationDto(target, operation, properties.toPropertyDtos())
