package org.ktcs.adapters.loopback

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation
import kotlin.math.atan2
import kotlin.math.roundToLong

/**
 * A step as the simulation drives it: a straight line from [from] to [to] (either `null` if the point has no known
 * position) that is [length] mm long as the model says, at up to [maxVelocity] mm/s, facing [heading] degrees
 * (`NaN` if unknown).
 */
internal data class Leg(
    val from: Position?,
    val to: Position?,
    val length: Double,
    val maxVelocity: Double,
    val heading: Double,
) {
    /** Where the vehicle is after [distance] mm, interpolated along the straight line. */
    fun positionAt(distance: Double): Position? {
        if (from == null || to == null || length <= 0.0) return to
        val share = (distance / length).coerceIn(0.0, 1.0)
        fun along(start: Long, end: Long) = start + ((end - start) * share).roundToLong()
        return Position(along(from.x, to.x), along(from.y, to.y), along(from.z, to.z))
    }

    companion object {
        /** Velocity for a path or vehicle that gives none (0), as openTCS's loopback does. */
        const val FALLBACK_VELOCITY: Double = 100.0

        /** The leg for [step], or `null` if its path is not in [model]. */
        fun of(step: Step, model: PlantModel, vehicle: Vehicle): Leg? {
            val path = step.path?.let { model.path(it) ?: return null }
            val from = step.sourcePoint?.let(model::point)?.pose?.position
            val to = model.point(step.destinationPoint)?.pose?.position
            val backward = step.vehicleOrientation == VehicleOrientation.BACKWARD
            val pathLimit = if (backward) path?.maxReverseVelocity else path?.maxVelocity
            val vehicleLimit = if (backward) vehicle.maxReverseVelocity else vehicle.maxVelocity
            val maxVelocity = minOf(velocity(pathLimit ?: 0), velocity(vehicleLimit))
            return Leg(from, to, (path?.length ?: 0L).toDouble(), maxVelocity, heading(from, to, backward))
        }

        private fun velocity(limit: Int) = if (limit > 0) limit.toDouble() else FALLBACK_VELOCITY

        private fun heading(from: Position?, to: Position?, backward: Boolean): Double {
            if (from == null || to == null || (from.x == to.x && from.y == to.y)) return Double.NaN
            val travel = Math.toDegrees(atan2((to.y - from.y).toDouble(), (to.x - from.x).toDouble()))
            return if (backward) normalize(travel + 180.0) else travel
        }

        /** Maps [degrees] into (-180, 180]. */
        private fun normalize(degrees: Double): Double = if (degrees > 180.0) degrees - 360.0 else degrees
    }
}
