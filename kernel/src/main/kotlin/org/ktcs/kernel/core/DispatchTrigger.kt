package org.ktcs.kernel.core

import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.kernel.Cancellable
import org.ktcs.kernel.context.KernelContext

/**
 * Runs the dispatcher soon after something may have become assignable, and periodically as a safety net. Many
 * requests in one kernel task lead to one run. A new order waits up to [newOrderDelayMillis] for its run: a run
 * passes over every waiting order, so orders created one after another by a client would otherwise each pay for a
 * pass over thousands; any other request runs it at once.
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

    /** Asks for a dispatcher run after the current kernel task. */
    fun request() = schedule(0)

    /** Asks for a run for an order that became dispatchable: within [newOrderDelayMillis]. */
    fun requestForNewOrder() = schedule(newOrderDelayMillis)

    // A run due later is brought forward by a request for one at once; otherwise one pending run serves all requests.
    private fun schedule(delayMillis: Long) {
        val pending = scheduled
        if (pending != null && (delayMillis > 0 || !scheduledLater)) return
        pending?.cancel()
        scheduledLater = delayMillis > 0
        scheduled = context.schedule(delayMillis) {
            scheduled = null
            scheduledLater = false
            dispatcher().dispatch()
        }
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
