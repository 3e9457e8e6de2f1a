package org.ktcs.adapters.loopback

import kotlin.math.max
import kotlin.math.sqrt

/**
 * A stretch of constant [acceleration] (negative: braking), in mm, mm/s, mm/s² and seconds.
 */
data class Phase(val startVelocity: Double, val acceleration: Double, val durationSeconds: Double) {
    val endVelocity: Double get() = startVelocity + acceleration * durationSeconds

    val distance: Double get() = distanceAt(durationSeconds)

    /** The distance covered [seconds] into the phase. */
    fun distanceAt(seconds: Double): Double = startVelocity * seconds + acceleration * seconds * seconds / 2

    /** The time it takes to cover [distance] from the start of the phase. */
    fun timeAt(distance: Double): Double = timeToCover(startVelocity, acceleration, distance)

    companion object {
        /** Solves `d = v·t + a·t²/2` for t, in the form that stays exact when `a` is small or negative. */
        fun timeToCover(velocity: Double, acceleration: Double, distance: Double): Double = when {
            distance <= 0.0 -> 0.0
            acceleration == 0.0 -> distance / velocity
            else -> 2 * distance / (velocity + sqrt(max(0.0, velocity * velocity + 2 * acceleration * distance)))
        }
    }
}

/** How a vehicle drives one path: consecutive [phases] starting at [startVelocity]. */
data class Motion(val startVelocity: Double, val phases: List<Phase>) {
    val durationSeconds: Double get() = phases.sumOf { it.durationSeconds }

    val length: Double get() = phases.sumOf { it.distance }

    val endVelocity: Double get() = phases.lastOrNull()?.endVelocity ?: startVelocity

    /** The distance covered [seconds] after the start, at most [length]. */
    fun distanceAt(seconds: Double): Double {
        var covered = 0.0
        var left = seconds
        for (phase in phases) {
            if (left <= phase.durationSeconds) return covered + phase.distanceAt(max(0.0, left))
            covered += phase.distance
            left -= phase.durationSeconds
        }
        return covered
    }

    /** The velocity [seconds] after the start. */
    fun velocityAt(seconds: Double): Double {
        var left = seconds
        for (phase in phases) {
            if (left <= phase.durationSeconds) return phase.startVelocity + phase.acceleration * max(0.0, left)
            left -= phase.durationSeconds
        }
        return endVelocity
    }

    /** The seconds after the start at which [distance] is covered, at most [durationSeconds]. */
    fun timeAt(distance: Double): Double {
        var elapsed = 0.0
        var left = distance
        for (phase in phases) {
            if (left <= phase.distance) return elapsed + phase.timeAt(left)
            elapsed += phase.durationSeconds
            left -= phase.distance
        }
        return elapsed
    }
}
