package org.ktcs.api.order

/**
 * A way through the roadmap, computed by a router.
 *
 * @property costs the summed costs of the router's cost functions.
 */
public data class Route(val steps: List<Step>, val costs: Long) {
    /** The point the route ends at, or `null` for a route without steps. */
    val finalDestinationPoint: String? get() = steps.lastOrNull()?.destinationPoint
}

/**
 * One movement along a route: from [sourcePoint] (`null` for a route that starts where the vehicle already is) over
 * [path] to [destinationPoint].
 *
 * @property routeIndex position of this step in its route, from 0.
 * @property executionAllowed `false` when a locked path keeps the vehicle from going further yet.
 */
public data class Step(
    val path: String?,
    val sourcePoint: String?,
    val destinationPoint: String,
    val vehicleOrientation: VehicleOrientation = VehicleOrientation.FORWARD,
    val routeIndex: Int = 0,
    val executionAllowed: Boolean = true,
)

/** The direction a vehicle drives a path in. */
public enum class VehicleOrientation { FORWARD, BACKWARD, UNDEFINED }
