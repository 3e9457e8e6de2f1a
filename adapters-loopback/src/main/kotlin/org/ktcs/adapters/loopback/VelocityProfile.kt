package org.ktcs.adapters.loopback

import kotlin.math.abs
import kotlin.math.sqrt

/**
 * Plans trapezoidal velocity profiles analytically, so a simulated vehicle needs one scheduled event per path
 * instead of a tick every 100 ms. Units: mm, mm/s, mm/s², seconds.
 */
object VelocityProfile {
    /**
     * How a vehicle drives [length] starting at [startVelocity]: it speeds up (or slows down) towards [maxVelocity],
     * cruises, and brakes to a stop at the end if [stopAtEnd]; otherwise it keeps its velocity for the next path.
     * A vehicle too fast to stop within [length] brakes all the way and arrives still moving.
     */
    fun plan(
        length: Double,
        startVelocity: Double,
        maxVelocity: Double,
        acceleration: Double,
        deceleration: Double,
        stopAtEnd: Boolean,
    ): Motion {
        require(length >= 0.0) { "length must not be negative, was $length" }
        require(startVelocity >= 0.0) { "startVelocity must not be negative, was $startVelocity" }
        require(maxVelocity > 0.0) { "maxVelocity must be positive, was $maxVelocity" }
        require(acceleration > 0.0 && deceleration > 0.0) { "acceleration and deceleration must be positive" }
        val ramps = Ramps(acceleration, deceleration)
        val phases = if (stopAtEnd) {
            ramps.stopping(length, startVelocity, maxVelocity)
        } else {
            ramps.rolling(length, startVelocity, maxVelocity)
        }
        return Motion(startVelocity, phases.filter { it.durationSeconds > 0.0 })
    }

    private class Ramps(val acceleration: Double, val deceleration: Double) {
        fun stopping(length: Double, v0: Double, vMax: Double): List<Phase> {
            val rampsLength = distance(v0, vMax) + distance(vMax, 0.0)
            return when {
                rampsLength <= length -> listOf(ramp(v0, vMax), cruise(vMax, length - rampsLength), ramp(vMax, 0.0))

                v0 * v0 >= 2 * deceleration * length -> listOf(over(length, v0, -deceleration))

                else -> {
                    // Peak where the speed-up and the braking distance together fill the path exactly.
                    val peak = sqrt(
                        (2 * acceleration * deceleration * length + deceleration * v0 * v0) /
                            (acceleration + deceleration),
                    )
                    listOf(ramp(v0, peak), ramp(peak, 0.0))
                }
            }
        }

        fun rolling(length: Double, v0: Double, vMax: Double): List<Phase> {
            val rampLength = distance(v0, vMax)
            if (rampLength <= length) return listOf(ramp(v0, vMax), cruise(vMax, length - rampLength))
            return listOf(over(length, v0, if (vMax > v0) acceleration else -deceleration))
        }

        private fun rate(from: Double, to: Double) = if (to >= from) acceleration else deceleration

        private fun distance(from: Double, to: Double) = abs(to * to - from * from) / (2 * rate(from, to))

        private fun ramp(from: Double, to: Double): Phase {
            val rate = rate(from, to)
            return Phase(from, if (to >= from) rate else -rate, abs(to - from) / rate)
        }

        private fun cruise(velocity: Double, length: Double) = Phase(velocity, 0.0, length / velocity)

        private fun over(length: Double, v0: Double, acceleration: Double) =
            Phase(v0, acceleration, Phase.timeToCover(v0, acceleration, length))
    }
}
