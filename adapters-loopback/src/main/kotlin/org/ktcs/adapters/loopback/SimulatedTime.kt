package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import kotlin.math.max
import kotlin.math.roundToLong

/**
 * The kernel clock seen through the simulation's time factor: simulated ms pass [timeFactor] times faster. The
 * factor may change while the simulation runs; simulated time goes on from where it was.
 *
 * While a timer's action runs, the simulated time is the moment the timer was due, not the later moment the busy
 * kernel thread got to run it: what the action starts (the next step, the next operation) starts then, so a vehicle
 * whose timers run late catches up instead of losing the delay at every step. At time factor 100 a 2 m step takes
 * 20 ms of wall time, and a timer 2 ms late would otherwise slow the vehicle by a tenth. A timer off by less than
 * the clock's millisecond is on time. The simulated time never goes back: a timer that runs late after the time was read meanwhile starts its action from the time last read.
 */
internal class SimulatedTime(private val clock: KernelClock, timeFactor: Double) {
    var timeFactor: Double = timeFactor
        private set
    private var simulatedAtChange = 0.0
    private var clockAtChange = clock.elapsedMillis()

    /** The simulated ms the timer whose action runs now was due at; `null` outside timers' actions. */
    private var due: Double? = null

    /** The latest simulated time read, so that it never goes back. */
    private var latest = 0.0

    fun nowMillis(): Double = max(due ?: clockMillis(), latest).also { latest = it }

    /** Runs [action] in the kernel context after [delayMillis] of simulated time. */
    fun schedule(delayMillis: Double, action: () -> Unit): Cancellable {
        val at = nowMillis() + delayMillis
        val wallDelay = ((at - clockMillis()) / timeFactor).roundToLong().coerceAtLeast(0)
        return clock.schedule(wallDelay) {
            val outer = due
            // The clock counts whole milliseconds, so a timer runs up to half of one off its exact time; only a timer
            // late by a whole millisecond or more ran late. (Aligning every timer exactly made the vehicles on a grid
            // move in lockstep, and their simultaneous claims deadlocked far more often: 40x40, 5 seeds.)
            due = if ((clockMillis() - at) / timeFactor >= 1.0) at else null
            try {
                action()
            } finally {
                due = outer
            }
        }
    }

    /** From now on simulated time runs [factor] times faster than the clock; timers already set keep their delay. */
    fun changeFactor(factor: Double) {
        require(factor > 0.0 && factor.isFinite()) { "the time factor must be positive, was $factor" }
        simulatedAtChange = nowMillis()
        clockAtChange = clock.elapsedMillis()
        timeFactor = factor
    }

    private fun clockMillis(): Double = simulatedAtChange + (clock.elapsedMillis() - clockAtChange) * timeFactor
}
