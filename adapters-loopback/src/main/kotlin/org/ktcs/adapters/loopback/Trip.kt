package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Cancellable
import kotlin.math.floor

/**
 * Drives a vehicle along [motion] up to [endDistance] (the path's length, or less where the battery runs out):
 * calls [onProgress] with the distance covered every [reportIntervalMillis] of simulated time (never if 0), then
 * [onEnd]. Starts paused.
 */
internal class Trip(
    private val time: SimulatedTime,
    val motion: Motion,
    endDistance: Double,
    private val reportIntervalMillis: Long,
    private val onProgress: (Double) -> Unit,
    private val onEnd: () -> Unit,
) {
    var endDistance: Double = endDistance
        private set
    private var timer = timerFor(endDistance, 0.0)
    private var nextReport = 1L
    private var reportHandle: Cancellable? = null

    val isRunning: Boolean get() = timer.isRunning

    /** The distance covered so far. */
    val distance: Double get() = motion.distanceAt(timer.elapsedMillis / 1000)

    val velocity: Double get() = motion.velocityAt(timer.elapsedMillis / 1000)

    fun start() {
        if (timer.isRunning) return
        timer.start()
        if (reportIntervalMillis > 0) {
            nextReport = floor(timer.elapsedMillis / reportIntervalMillis).toLong() + 1
            scheduleReport()
        }
    }

    fun pause() {
        timer.pause()
        reportHandle?.cancel()
        reportHandle = null
    }

    /** Moves the end to [distance], e.g. because the battery was recharged or drained by hand. */
    fun endAt(distance: Double) {
        val wasRunning = isRunning
        pause()
        endDistance = distance
        timer = timerFor(distance, timer.elapsedMillis)
        if (wasRunning) start()
    }

    private fun timerFor(distance: Double, elapsedMillis: Double) =
        PausableTimer(time, motion.timeAt(distance) * 1000, elapsedMillis) {
            reportHandle?.cancel()
            onEnd()
        }

    private fun scheduleReport() {
        val at = (nextReport * reportIntervalMillis).toDouble()
        if (at >= timer.durationMillis) return
        reportHandle = time.schedule(at - timer.elapsedMillis) {
            nextReport++
            onProgress(motion.distanceAt(at / 1000))
            if (isRunning) scheduleReport()
        }
    }
}
