package org.ktcs.kernel.dispatching

/** Property keys the default dispatcher reads, as openTCS names them. */
object DispatcherProperties {
    /** On a vehicle: the only park point it is sent to. */
    const val ASSIGNED_PARKING_POSITION: String = "tcs:assignedParkingPosition"

    /** On a vehicle: the park point it is sent to when that is free, before closer ones. */
    const val PREFERRED_PARKING_POSITION: String = "tcs:preferredParkingPosition"

    /** On a park point: its priority, lower is better; points without one rank after all others. */
    const val PARKING_POSITION_PRIORITY: String = "tcs:parkingPositionPriority"

    /** On a vehicle: the only location it is sent to for recharging. */
    const val ASSIGNED_RECHARGE_LOCATION: String = "tcs:assignedRechargeLocation"

    /** On a vehicle: the location it is sent to for recharging when that is free, before closer ones. */
    const val PREFERRED_RECHARGE_LOCATION: String = "tcs:preferredRechargeLocation"

    /** On an order: comma-separated names of points, paths and locations its routes must avoid. */
    const val RESOURCES_TO_AVOID: String = "tcs:resourcesToAvoid"
}

/** The type of the parking orders the dispatcher creates (openTCS `OrderConstants.TYPE_PARK`). */
const val PARK_ORDER_TYPE: String = "Park"

/** The type of the recharge orders the dispatcher creates (openTCS `OrderConstants.TYPE_CHARGE`). */
const val CHARGE_ORDER_TYPE: String = "Charge"
