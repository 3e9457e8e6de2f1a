package org.ktcs.kernel.core

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * The DISPATCHABLE orders, oldest first, kept up to date from the order events ([track]) and changed nowhere else;
 * it also runs the dispatcher when an order becomes dispatchable or a vehicle becomes free. Kernel context.
 */
internal class DispatchableOrders(
    private val state: KernelState,
    private val trigger: DispatchTrigger,
    private val onVehicleFree: (String) -> Unit,
) {
    private val orders = LinkedHashMap<String, TransportOrder>()

    /** A read-only view, oldest first. */
    fun all(): Collection<TransportOrder> = orders.values

    /** Puts back a DISPATCHABLE order read from the state store at start (no event: nothing changed). */
    fun restore(order: TransportOrder) {
        orders[order.name] = order
    }

    /** Forgets them all, when the plant model is replaced. */
    fun clear() = orders.clear()

    fun track(event: KernelEvent) {
        when (event) {
            is TransportOrderEvent -> trackOrder(event)
            is OrderSequenceEvent -> releaseFinishedSequence(event)
            else -> Unit
        }
    }

    private fun trackOrder(event: TransportOrderEvent) {
        val order = event.current
        if (order == null || order.state != TransportOrderState.DISPATCHABLE) {
            (order ?: event.previous)?.let { orders.remove(it.name) }
            if (order != null && order.state.isFinal && order.processingVehicle != null) {
                onVehicleFree(order.processingVehicle!!)
            }
            return
        }
        val before = orders.put(order.name, order)
        when {
            before == null -> trigger.requestForNewOrder(order.name)

            // Given its vehicle and routes, the order leaves the dispatchable ones in the same kernel task: the
            // assignment changed nothing another order could be given by.
            order.processingVehicle != null && before.processingVehicle == null -> Unit

            !before.sameForDispatching(order) -> trigger.request()
        }
    }

    // A waiting order's history changes at every new reason; what a dispatcher decides by must be asked about again.
    private fun TransportOrder.sameForDispatching(other: TransportOrder): Boolean = driveOrders == other.driveOrders &&
        type == other.type &&
        intendedVehicle == other.intendedVehicle &&
        deadline == other.deadline &&
        dispensable == other.dispensable &&
        wrappingSequence == other.wrappingSequence &&
        properties == other.properties

    // A sequence's progress decides which of its waiting orders a free vehicle may take: a full run looks again.
    private fun releaseFinishedSequence(event: OrderSequenceEvent) {
        trigger.request()
        val sequence = event.current ?: return
        if (!sequence.finished || event.previous?.finished == true) return
        state.plant.vehicles().filter { it.orderSequence == sequence.name }.forEach { vehicle ->
            state.plant.updateVehicle(vehicle.name) { it.copy(orderSequence = null) }
        }
    }
}
