package org.ktcs.kernel.core

import org.ktcs.api.event.UserNotification
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.orders.OrderLifecycle

/**
 * How the state store puts a previous run back into the kernel: [restore a stored object][order] as it was, before
 * the kernel starts (no events), and [continue][continueOrder] or [fail][failOrder] what was under way right after it
 * started. Runs in the kernel context.
 */
class KernelRestoration internal constructor(
    private val kernel: KernelCore,
    private val state: KernelState,
    private val lifecycle: OrderLifecycle,
) {
    /** Generated names continue after the stored position. */
    fun names(millis: Long, counter: Long) = state.names.resumeAfter(millis, counter)

    fun sequence(sequence: OrderSequence) = state.sequences.restore(sequence)

    fun order(order: TransportOrder) = state.orders.restore(order)

    fun notifications(notifications: List<UserNotification>) = state.notifications.restore(notifications)

    fun pathLock(path: String, locked: Boolean) {
        state.plant.setPathLocked(path, locked)
    }

    fun locationLock(location: String, locked: Boolean) {
        state.plant.setLocationLocked(location, locked)
    }

    /** Restores the stored runtime state of [vehicle] (position, energy, settings). */
    fun vehicle(vehicle: String, stored: (Vehicle) -> Vehicle) {
        state.plant.updateVehicle(vehicle, stored)
    }

    /** [vehicle] works on [sequence] again. */
    fun sequenceOf(vehicle: String, sequence: String) {
        state.plant.updateVehicle(vehicle) { it.copy(orderSequence = sequence) }
    }

    /** A stored order that is neither under way nor dispatchable takes its place in the life cycle again. */
    fun settled(order: TransportOrder) = when (order.state) {
        TransportOrderState.DISPATCHABLE -> kernel.restoreDispatchable(order)
        else -> lifecycle.onRestored(order)
    }

    /** The order [vehicle]'s controller works on now, or null. */
    fun busyWith(vehicle: String): String? = state.controllers.controller(vehicle).transportOrder

    /**
     * [order]'s vehicle continues it from drive order [index] on [routed] (the rest of its drive orders routed again
     * from where the vehicle stands); the history says why with [code] and [supplement].
     */
    fun continueOrder(order: TransportOrder, index: Int, routed: List<DriveOrder>, code: String, supplement: String) {
        val vehicle = checkNotNull(order.processingVehicle) { "transport order '${order.name}' has no vehicle" }
        state.orders.update(order.name) { it.copy(driveOrders = it.driveOrders.take(index) + routed) }
        state.orders.addHistory(order.name, code, supplement)
        order.wrappingSequence?.let { sequenceOf(vehicle, it) }
        state.controllers.controller(vehicle).resume(state.orders.require(order.name), index)
    }

    /** [order], which was under way when the kernel stopped, fails as withdrawn; the history says why. */
    fun failOrder(order: TransportOrder, code: String, supplement: String, failure: String) {
        state.orders.addHistory(order.name, code, supplement)
        if (order.state != TransportOrderState.WITHDRAWN) {
            state.orders.transition(
                order.name,
                TransportOrderState.WITHDRAWN,
            )
        }
        state.orders.transition(order.name, TransportOrderState.FAILED, failure)
    }
}
