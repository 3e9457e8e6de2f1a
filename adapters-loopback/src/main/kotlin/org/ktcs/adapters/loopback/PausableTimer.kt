package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable

/**
 * Runs [action] once [durationMillis] of simulated time have passed while the timer was running; time spent paused
 * does not count. Starts paused, with [elapsedMillis] already used up.
 */
internal class PausableTimer(
    private val time: SimulatedTime,
    val durationMillis: Double,
    elapsedMillis: Double = 0.0,
    private val action: () -> Unit,
) {
    private var elapsedBefore = elapsedMillis.coerceIn(0.0, durationMillis)
    private var runningSince: Double? = null
    private var handle: Cancellable? = null

    val isRunning: Boolean get() = runningSince != null

    val elapsedMillis: Double
        get() = (elapsedBefore + (runningSince?.let { time.nowMillis() - it } ?: 0.0)).coerceAtMost(durationMillis)

    fun start() {
        if (isRunning) return
        runningSince = time.nowMillis()
        handle = time.schedule(durationMillis - elapsedBefore) {
            handle = null
            runningSince = null
            elapsedBefore = durationMillis
            action()
        }
    }

    fun pause() {
        if (!isRunning) return
        elapsedBefore = elapsedMillis
        runningSince = null
        handle?.cancel()
        handle = null
    }
}
