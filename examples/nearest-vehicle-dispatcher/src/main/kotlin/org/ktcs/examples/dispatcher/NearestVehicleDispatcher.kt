package org.ktcs.examples.dispatcher

import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder

/**
 * Gives each free order to the free vehicle with the cheapest route to the order's first destination, whatever its
 * energy or idle time (kTCS's default ranks vehicles by those first). Everything else (orders for an intended
 * vehicle or in a sequence, parking, recharging) is left to [others], normally kTCS's default dispatcher, which
 * runs right after.
 */
class NearestVehicleDispatcher(private val context: DispatchContext, private val others: Dispatcher) : Dispatcher {
    override fun initialize() = others.initialize()

    override fun terminate() = others.terminate()

    // snippet:nearest-dispatch
    override fun dispatch() {
        // A vehicle given an order in this run still looks free until the kernel has processed the assignment.
        val taken = HashSet<String>()
        context.dispatchableOrders()
            .filter { it.intendedVehicle == null && it.wrappingSequence == null }
            .forEach { order -> assignNearest(order, taken) }
        others.dispatch()
    }

    private fun assignNearest(order: TransportOrder, taken: MutableSet<String>) {
        val nearest = context.vehicles()
            .filter { it.name !in taken && isFree(it) }
            .mapNotNull { offer(it, order) }
            .minByOrNull { it.costs }
            ?: return
        context.assign(order.name, nearest.vehicle, nearest.driveOrders)
        taken += nearest.vehicle
    }
    // end-snippet

    private fun offer(vehicle: Vehicle, order: TransportOrder): Offer? {
        if (!vehicle.allowedOrderTypes.any { it == Vehicle.ANY_ORDER_TYPE || it == order.type }) return null
        if (!context.driverAccepts(vehicle.name, order).isYes) return null
        val position = vehicle.currentPosition ?: return null
        val driveOrders = context.router.routeOrder(vehicle, position, order) ?: return null
        val costs = driveOrders.first().route?.costs ?: return null
        return Offer(vehicle.name, driveOrders, costs)
    }

    /** Utilized, not paused, not charging, with energy above critical, and idle or only parking. */
    private fun isFree(vehicle: Vehicle): Boolean {
        if (vehicle.integrationLevel != IntegrationLevel.TO_BE_UTILIZED || vehicle.paused) return false
        if (vehicle.state !in setOf(VehicleState.IDLE, VehicleState.EXECUTING)) return false
        if (vehicle.energyLevel <= vehicle.energyLevelThresholdSet.critical) return false
        val current = vehicle.transportOrder ?: return vehicle.state == VehicleState.IDLE
        return context.transportOrder(current)?.dispensable == true
    }

    private class Offer(val vehicle: String, val driveOrders: List<DriveOrder>, val costs: Long)
}
