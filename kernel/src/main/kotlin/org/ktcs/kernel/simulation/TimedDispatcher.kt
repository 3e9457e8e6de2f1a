package org.ktcs.kernel.simulation

import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.kernel.dispatching.IncrementalDispatcher

/**
 * A dispatcher that records its runs: how long each takes on the wall clock, and when the one under way started on
 * [elapsedMillis] (the kernel clock), so that an assignment's latency splits into the wait for the run and the run.
 * Runs on changes stay runs on changes.
 */
internal class TimedDispatcher(
    private val dispatcher: Dispatcher,
    private val elapsedMillis: () -> Long,
) : IncrementalDispatcher {
    val durationsNanos = ArrayList<Long>()

    /** When the run under way started, or `null` between runs. */
    var runStartedAt: Long? = null
        private set

    override fun initialize() = dispatcher.initialize()

    override fun terminate() = dispatcher.terminate()

    override fun dispatch() = timed { dispatcher.dispatch() }

    override fun dispatchChanges(newOrders: Collection<String>) = timed {
        if (dispatcher is IncrementalDispatcher) dispatcher.dispatchChanges(newOrders) else dispatcher.dispatch()
    }

    private inline fun timed(block: () -> Unit) {
        runStartedAt = elapsedMillis()
        val start = System.nanoTime()
        try {
            block()
        } finally {
            durationsNanos += System.nanoTime() - start
            runStartedAt = null
        }
    }
}
