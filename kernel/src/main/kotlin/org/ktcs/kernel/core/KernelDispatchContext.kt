package org.ktcs.kernel.core

import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.kernel.Explained
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.routing.Router
import org.ktcs.kernel.orders.HistoryCodes

/**
 * What the dispatcher may see and do, backed by the kernel. An order given to a vehicle that is still busy with a
 * dispensable order is reserved for it: the dispensable order is withdrawn regularly, and the reserved order is
 * routed from wherever the vehicle stops and assigned then.
 */
class KernelDispatchContext(private val kernel: KernelCore, private val state: KernelState) : DispatchContext {
    private val reservations = HashMap<String, String>()

    override val clock: KernelClock get() = kernel.context

    override val router: Router get() = kernel.router

    override fun plantModel(): PlantModel = state.plant.layoutWithLocks()

    override fun vehicles(): Collection<Vehicle> = state.plant.vehicles()

    override fun dispatchableOrders(): Collection<TransportOrder> =
        kernel.dispatchableOrders().filter { it.name !in reservations }

    override fun transportOrder(name: String): TransportOrder? = state.orders.get(name)

    override fun orderSequence(name: String): OrderSequence? = state.sequences.get(name)

    override fun driverAccepts(vehicle: String, order: TransportOrder): Explained =
        state.controllers.controller(vehicle).driver?.canProcess(order)
            ?: Explained.no("vehicle $vehicle has no driver")

    override fun assign(order: String, vehicle: String, driveOrders: List<DriveOrder>) {
        val controller = state.controllers.controller(vehicle)
        val busyWith = controller.transportOrder
        if (busyWith == null) {
            kernel.assign(order, vehicle, driveOrders)
            return
        }
        if (!state.orders.require(busyWith).dispensable) {
            throw IllegalStateChangeException(
                "vehicle '$vehicle' is processing order '$busyWith', which is not dispensable",
            )
        }
        reservations[order] = vehicle
        controller.withdraw(immediate = false, reason = "replaced by order $order")
    }

    /** The vehicle finished or gave up its order: if an order was reserved for it, route and assign that now. */
    fun onVehicleFree(vehicle: String) {
        val order = reservations.entries.firstOrNull { it.value == vehicle }?.key ?: return
        reservations.remove(order)
        // The order waits among the others again (if not assigned below), which a run on changes would not see.
        kernel.dispatch()
        val current = state.orders.get(order)?.takeIf { it.state == TransportOrderState.DISPATCHABLE } ?: return
        val position = state.plant.vehicle(vehicle).currentPosition ?: return
        kernel.router.routeOrder(state.plant.vehicle(vehicle), position, current)?.let {
            kernel.assign(order, vehicle, it)
        }
    }

    override fun createTransportOrder(creation: TransportOrderCreation): TransportOrder = kernel.createTransportOrder(
        creation,
    )

    override fun vehicleWaiting(vehicle: String, reason: String?) {
        if (state.plant.vehicleOrNull(vehicle)?.waitingReason == reason) return
        state.plant.updateVehicle(vehicle) { it.copy(waitingReason = reason) }
    }

    override fun orderWaiting(order: String, reason: String) {
        state.orders.update(order) { current ->
            val last = current.history.lastOrNull { it.eventCode == HistoryCodes.ORDER_DISPATCHING_DEFERRED }
            if (last?.supplement == reason) {
                current
            } else {
                val entry = HistoryEntry(kernel.context.now(), HistoryCodes.ORDER_DISPATCHING_DEFERRED, reason)
                current.copy(history = current.history + entry)
            }
        }
    }
}
