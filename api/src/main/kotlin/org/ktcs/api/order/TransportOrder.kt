package org.ktcs.api.order

import java.time.Instant

/**
 * A job for a vehicle: visit [driveOrders]' destinations in order.
 *
 * @property type matched against the vehicles' acceptable order types.
 * @property intendedVehicle the vehicle that must do this order, or `null` for any.
 * @property processingVehicle the vehicle doing it, once assigned.
 * @property dependencies orders that must be FINISHED before this one may be dispatched.
 * @property wrappingSequence the order sequence this order belongs to, if any.
 * @property dispensable a dispensable order (parking, recharging) may be withdrawn for a better one.
 * @property currentDriveOrderIndex index of the drive order being worked on, -1 before the first.
 * @property currentRouteStepIndex index of the step of the current route being driven, -1 before the first.
 */
public data class TransportOrder(
    val name: String,
    val driveOrders: List<DriveOrder>,
    val type: String = DEFAULT_TYPE,
    val state: TransportOrderState = TransportOrderState.RAW,
    val creationTime: Instant,
    val deadline: Instant = Instant.MAX,
    val finishedTime: Instant? = null,
    val intendedVehicle: String? = null,
    val processingVehicle: String? = null,
    val dependencies: Set<String> = emptySet(),
    val wrappingSequence: String? = null,
    val dispensable: Boolean = false,
    val peripheralReservationToken: String? = null,
    val currentDriveOrderIndex: Int = -1,
    val currentRouteStepIndex: Int = -1,
    val properties: Map<String, String> = emptyMap(),
    val history: List<HistoryEntry> = emptyList(),
) {
    /** The drive order being worked on, or `null`. */
    val currentDriveOrder: DriveOrder? get() = driveOrders.getOrNull(currentDriveOrderIndex)

    public companion object {
        /** The type of an order created without one; openTCS calls it "-". */
        public const val DEFAULT_TYPE: String = "-"
    }
}

/**
 * One leg of a transport order: drive to [destination] and perform its operation.
 *
 * @property name unique within its transport order.
 * @property route set by the dispatcher when the order is assigned.
 */
public data class DriveOrder(
    val name: String,
    val destination: Destination,
    val route: Route? = null,
    val state: DriveOrderState = DriveOrderState.PRISTINE,
)

/**
 * Where a drive order goes and what happens there.
 *
 * @property target a location name, or a point name with [Operations.MOVE] / [Operations.PARK].
 */
public data class Destination(
    val target: String,
    val operation: String,
    val properties: Map<String, String> = emptyMap(),
)

/** Operations with a fixed meaning. */
public object Operations {
    /** Drive to a point and do nothing. */
    public const val MOVE: String = "MOVE"

    /** Drive to a point and park there. */
    public const val PARK: String = "PARK"

    /** Do nothing at a location. */
    public const val NOP: String = "NOP"
}

/** Something that happened to an object, for its history. */
public data class HistoryEntry(val timestamp: Instant, val eventCode: String, val supplement: String = "")
