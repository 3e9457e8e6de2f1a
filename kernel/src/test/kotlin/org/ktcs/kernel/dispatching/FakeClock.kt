package org.ktcs.kernel.dispatching

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import java.time.Instant

/** A clock that only moves when a test says so; the dispatcher must not schedule anything on it. */
class FakeClock(var now: Instant = Instant.parse("2026-01-01T08:00:00Z")) : KernelClock {
    override fun now(): Instant = now

    override fun elapsedMillis(): Long = now.toEpochMilli()

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable =
        error("the dispatcher keeps no timers, but scheduled something in $delayMillis ms")

    fun advance(millis: Long) {
        now = now.plusMillis(millis)
    }
}
