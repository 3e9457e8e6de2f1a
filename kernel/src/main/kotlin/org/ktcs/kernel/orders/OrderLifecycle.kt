package org.ktcs.kernel.orders

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.order.TransportOrderState.ACTIVE
import org.ktcs.api.order.TransportOrderState.DISPATCHABLE
import org.ktcs.api.order.TransportOrderState.FAILED
import org.ktcs.api.order.TransportOrderState.FINISHED
import org.ktcs.api.order.TransportOrderState.RAW
import org.ktcs.api.order.TransportOrderState.UNROUTABLE
import org.ktcs.api.order.TransportOrderState.WITHDRAWN
import org.ktcs.api.routing.Router
import java.time.Instant

/**
 * The kernel's side of the order life cycle, reacting to order events: a new order is checked (RAW → ACTIVE or
 * UNROUTABLE) and becomes DISPATCHABLE once its dependencies are FINISHED; a final order updates its sequence and
 * releases the orders that depend on it; in a failure-fatal sequence a failed order fails the ones after it.
 *
 * Work per event is proportional to the order's dependants, found through an index, not a scan of all orders.
 */
class OrderLifecycle(
    private val orders: TransportOrderPool,
    private val sequences: OrderSequencePool,
    private val router: () -> Router,
    private val dismissUnroutable: Boolean = true,
) {
    private val dependants = HashMap<String, MutableSet<String>>()

    fun onEvent(event: KernelEvent) {
        if (event !is TransportOrderEvent) return
        val order = event.current ?: return
        if (event.previous == null) {
            onCreated(order)
        } else if (event.previous?.state != order.state && order.state.isFinal) {
            onFinal(order)
        }
    }

    /**
     * Takes up an order of a previous run: indexes what it waits for, and carries a RAW or ACTIVE one on as a new
     * one would be (the run may have stopped between its creation and its activation).
     */
    fun onRestored(order: TransportOrder) {
        if (order.state.isFinal) return
        order.dependencies.forEach { dependants.getOrPut(it) { mutableSetOf() } += order.name }
        if (order.state == RAW) {
            if (dismissUnroutable && !router().isGenerallyRoutable(order)) {
                orders.transition(order.name, UNROUTABLE, "no route connects the destinations")
                return
            }
            orders.transition(order.name, ACTIVE)
        }
        activateIfReady(order.name)
    }

    private fun onCreated(order: TransportOrder) {
        order.dependencies.forEach { dependants.getOrPut(it) { mutableSetOf() } += order.name }
        order.wrappingSequence?.let { sequence ->
            sequences.update(sequence) {
                it.copy(
                    orders = it.orders + order.name,
                    history =
                    it.history + HistoryEntry(order.creationTime, HistoryCodes.SEQUENCE_ORDER_APPENDED, order.name),
                )
            }
        }
        if (dismissUnroutable && !router().isGenerallyRoutable(order)) {
            orders.transition(order.name, UNROUTABLE, "no route connects the destinations")
            return
        }
        orders.transition(order.name, ACTIVE)
        activateIfReady(order.name)
    }

    private fun activateIfReady(name: String) {
        val order = orders.get(name) ?: return
        if (order.state != ACTIVE) return
        val waitingFor = order.dependencies.filter { orders.get(it)?.state != FINISHED }
        if (waitingFor.isNotEmpty()) {
            val reason = dependenciesText(waitingFor)
            if (order.waitingReason() != reason) noteWaiting(order, reason)
        } else {
            if (order.waitingReason() != null) noteWaiting(order, null)
            orders.transition(name, DISPATCHABLE)
        }
    }

    private fun dependenciesText(unfinished: List<String>): String {
        val failed = unfinished.filter { orders.get(it)?.state?.isFinal == true }
        val open = unfinished - failed.toSet()
        val parts = listOfNotNull(
            open.takeIf { it.isNotEmpty() }?.let { "dependencies not finished: ${it.sorted().joinToString()}" },
            failed.takeIf { it.isNotEmpty() }?.let {
                "dependencies failed, so it never becomes dispatchable (withdraw it): ${it.sorted().joinToString()}"
            },
        )
        return parts.joinToString("; ")
    }

    /** Records why an ACTIVE order waits ([reason]), or that it no longer does (`null`), in its history. */
    private fun noteWaiting(order: TransportOrder, reason: String?) {
        if (reason == null) {
            orders.addHistory(order.name, HistoryCodes.ORDER_DISPATCHING_RESUMED, "dependencies finished")
        } else {
            orders.addHistory(order.name, HistoryCodes.ORDER_DISPATCHING_DEFERRED, reason)
        }
    }

    private fun onFinal(order: TransportOrder) {
        dependants.remove(order.name)?.forEach(::activateIfReady)
        order.wrappingSequence?.let { onSequenceOrderFinal(it, order) }
    }

    private fun onSequenceOrderFinal(sequenceName: String, order: TransportOrder) {
        val sequence = sequences.get(sequenceName) ?: return
        val index = sequence.orders.indexOf(order.name)
        if (order.state != FINISHED && sequence.failureFatal && !order.dispensable) {
            sequence.orders.drop(index + 1).forEach(::failUnfinished)
        }
        sequences.update(sequenceName) { current ->
            val finishedIndex = maxOf(current.finishedIndex, index)
            val finished = current.complete && finishedIndex == current.orders.lastIndex
            current.copy(
                finishedIndex = finishedIndex,
                finished = finished,
                finishedTime = if (finished) order.finishedTime else null,
                processingVehicle = if (finished) null else current.processingVehicle,
            )
        }
    }

    private fun failUnfinished(name: String) {
        val order = orders.get(name) ?: return
        if (order.state.isFinal) return
        if (order.state != WITHDRAWN) {
            orders.transition(name, WITHDRAWN, "an earlier order of its failure-fatal sequence failed")
        }
        orders.transition(name, FAILED, "an earlier order of its failure-fatal sequence failed")
    }

    /**
     * Called when a sequence is marked complete at [now]: it may be finished already, and then it finishes [now]
     * (as in openTCS), so that the sweep removes it in time.
     */
    fun onSequenceCompleted(name: String, now: Instant) {
        sequences.update(name) { current ->
            val allFinal = current.orders.all { orders.get(it)?.state?.isFinal ?: true }
            if (allFinal && !current.finished) {
                current.copy(finished = true, finishedTime = now, finishedIndex = current.orders.lastIndex)
            } else {
                current
            }
        }
    }

    companion object {
        /** States from which an order was never handed to a vehicle. */
        val UNASSIGNED: Set<TransportOrderState> = setOf(RAW, ACTIVE, DISPATCHABLE)
    }
}
