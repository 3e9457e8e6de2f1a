package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import java.time.Instant
import java.util.PriorityQueue

/** A kernel clock that only moves when a test advances it; scheduled actions run in time order, then FIFO. */
class VirtualClock(private val start: Instant = Instant.parse("2026-01-01T00:00:00Z")) : KernelClock {
    private class Scheduled(val at: Long, val sequence: Long, val action: () -> Unit)

    private val queue = PriorityQueue(compareBy<Scheduled> { it.at }.thenBy { it.sequence })
    private var sequence = 0L

    var nowMillis: Long = 0
        private set

    val scheduledActions: Int get() = queue.size

    /** How many actions have run so far. */
    var actionsRun: Long = 0
        private set

    override fun now(): Instant = start.plusMillis(nowMillis)

    override fun elapsedMillis(): Long = nowMillis

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable {
        require(delayMillis >= 0) { "negative delay $delayMillis" }
        val scheduled = Scheduled(nowMillis + delayMillis, sequence++, action)
        queue += scheduled
        return Cancellable { queue.remove(scheduled) }
    }

    /**
     * Stands at [millis] without running what is due by then: the timers due meanwhile then run late, at [millis],
     * as a busy machine's do.
     */
    fun jumpTo(millis: Long) {
        nowMillis = maxOf(nowMillis, millis)
    }

    /** Runs every action due up to [millis], then stands at [millis]. */
    fun advanceTo(millis: Long) {
        while (queue.peek()?.let { it.at <= millis } == true) runNext()
        nowMillis = maxOf(nowMillis, millis)
    }

    fun advanceBy(millis: Long) = advanceTo(nowMillis + millis)

    /** Runs actions until none is left; fails on what looks like an endless loop. */
    fun runUntilIdle(maxActions: Int = 1_000_000) {
        var count = 0
        while (queue.isNotEmpty()) {
            check(count++ < maxActions) { "still busy after $maxActions actions" }
            runNext()
        }
    }

    private fun runNext() {
        val next = queue.poll()
        nowMillis = maxOf(nowMillis, next.at)
        actionsRun++
        next.action()
    }
}
