package org.ktcs.kernel.core

import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.kernel.Cancellable
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.dispatching.IncrementalDispatcher

/**
 * Runs the dispatcher soon after something may have become assignable, and periodically as a safety net. Many
 * requests in one kernel task lead to one run. A new order waits up to [newOrderDelayMillis] for its run, so orders
 * created one after another by a client share it; any other request runs it at once.
 *
 * A run asked for only by new orders ([requestForNewOrder]) and vehicles ([requestForVehicle]) is a run on changes
 * ([IncrementalDispatcher.dispatchChanges], given the new orders) if the dispatcher can do one; any other request
 * ([request]: operators, locks, sequences, the periodic run) makes it a full run.
 */
class DispatchTrigger(
    private val context: KernelContext,
    private val dispatcher: () -> Dispatcher,
    private val periodMillis: Long,
    private val newOrderDelayMillis: Long = 0,
) {
    private var scheduled: Cancellable? = null
    private var scheduledLater = false
    private var periodic: Cancellable? = null
    private var fullRunDue = false
    private val newOrders = ArrayList<String>()

    /** Asks for a full dispatcher run after the current kernel task. */
    fun request() {
        fullRunDue = true
        schedule(0)
    }

    /** Asks for a run for [order], which became dispatchable: within [newOrderDelayMillis]. */
    fun requestForNewOrder(order: String) {
        newOrders += order
        schedule(newOrderDelayMillis)
    }

    /** Asks for a run after the current kernel task because a vehicle changed and may be able to take an order. */
    fun requestForVehicle() = schedule(0)

    // A run due later is brought forward by a request for one at once; otherwise one pending run serves all requests.
    private fun schedule(delayMillis: Long) {
        val pending = scheduled
        if (pending != null && (delayMillis > 0 || !scheduledLater)) return
        pending?.cancel()
        scheduledLater = delayMillis > 0
        scheduled = context.schedule(delayMillis) {
            scheduled = null
            scheduledLater = false
            run()
        }
    }

    private fun run() {
        val full = fullRunDue
        val orders = newOrders.toList()
        fullRunDue = false
        newOrders.clear()
        val current = dispatcher()
        if (!full && current is IncrementalDispatcher) current.dispatchChanges(orders) else current.dispatch()
    }

    fun start() {
        if (periodMillis <= 0) return
        periodic = context.schedule(periodMillis) {
            request()
            start()
        }
    }

    fun stop() {
        periodic?.cancel()
        periodic = null
    }
}
