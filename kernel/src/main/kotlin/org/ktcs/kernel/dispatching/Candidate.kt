package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder

/**
 * A vehicle that could do an order, with the order's drive orders routed from the vehicle's position. Before routing
 * (while candidates are only ranked by keys that need no route) [driveOrders] is empty.
 */
internal class Candidate(
    val vehicle: Vehicle,
    val order: TransportOrder,
    val driveOrders: List<DriveOrder> = emptyList(),
) {
    /** The costs of the routes to all destinations. */
    val completeCosts: Long get() = driveOrders.sumOf { it.route?.costs ?: 0 }

    /** The costs of the route to the first destination. */
    val initialCosts: Long get() = driveOrders.firstOrNull()?.route?.costs ?: 0

    fun routed(driveOrders: List<DriveOrder>): Candidate = Candidate(vehicle, order, driveOrders)

    override fun toString(): String = "${vehicle.name}->${order.name}"
}
