package org.ktcs.kernel.core

import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.kernel.Cancellable
import org.ktcs.kernel.context.KernelContext

/**
 * Runs the dispatcher soon after something may have become assignable, and periodically as a safety net. Many
 * requests in one kernel task lead to one run.
 */
class DispatchTrigger(
    private val context: KernelContext,
    private val dispatcher: () -> Dispatcher,
    private val periodMillis: Long,
) {
    private var scheduled = false
    private var periodic: Cancellable? = null

    /** Asks for a dispatcher run after the current kernel task. */
    fun request() {
        if (scheduled) return
        scheduled = true
        context.schedule(0) {
            scheduled = false
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
