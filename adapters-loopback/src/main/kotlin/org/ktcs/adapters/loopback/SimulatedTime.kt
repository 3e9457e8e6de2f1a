package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import kotlin.math.roundToLong

/**
 * The kernel clock seen through the simulation's time factor: simulated ms pass [timeFactor] times faster. The
 * factor may change while the simulation runs; simulated time goes on from where it was.
 */
internal class SimulatedTime(private val clock: KernelClock, timeFactor: Double) {
    var timeFactor: Double = timeFactor
        private set
    private var simulatedAtChange = 0.0
    private var clockAtChange = clock.elapsedMillis()

    fun nowMillis(): Double = simulatedAtChange + (clock.elapsedMillis() - clockAtChange) * timeFactor

    /** Runs [action] in the kernel context after [delayMillis] of simulated time. */
    fun schedule(delayMillis: Double, action: () -> Unit): Cancellable =
        clock.schedule((delayMillis / timeFactor).roundToLong().coerceAtLeast(0), action)

    /** From now on simulated time runs [factor] times faster than the clock; timers already set keep their delay. */
    fun changeFactor(factor: Double) {
        require(factor > 0.0 && factor.isFinite()) { "the time factor must be positive, was $factor" }
        simulatedAtChange = nowMillis()
        clockAtChange = clock.elapsedMillis()
        timeFactor = factor
    }
}
