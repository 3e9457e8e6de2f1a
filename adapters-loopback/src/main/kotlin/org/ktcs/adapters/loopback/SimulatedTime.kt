package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import kotlin.math.roundToLong

/** The kernel clock seen through the simulation's time factor: simulated ms pass [timeFactor] times faster. */
internal class SimulatedTime(private val clock: KernelClock, private val timeFactor: Double) {
    fun nowMillis(): Double = clock.elapsedMillis() * timeFactor

    /** Runs [action] in the kernel context after [delayMillis] of simulated time. */
    fun schedule(delayMillis: Double, action: () -> Unit): Cancellable =
        clock.schedule((delayMillis / timeFactor).roundToLong().coerceAtLeast(0), action)
}
