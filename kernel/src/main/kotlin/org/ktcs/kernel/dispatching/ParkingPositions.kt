package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle

/**
 * Finds park points for vehicles (openTCS's default and prioritized parking position suppliers): free park points
 * other than the vehicle's own, the one with the cheapest route first. The vehicle's `tcs:assignedParkingPosition`
 * is the only choice if set, its `tcs:preferredParkingPosition` comes first if free (an operator's choice for one
 * vehicle outranks the plant-wide priorities), then with priorities considered the best `tcs:parkingPositionPriority`
 * with a route wins, points without one last.
 */
internal class ParkingPositions(private val run: DispatchRun, private val free: FreePositions) {
    private val parkPoints by lazy { run.model.points.filter { it.type == PointType.PARK_POSITION } }

    fun isParkPosition(point: String?): Boolean = point?.let(run.model::point)?.type == PointType.PARK_POSITION

    /** The priority of the park point named [point], or `null` if it has none. */
    fun priority(point: String?): Int? = point?.let(run.model::point)?.let(::priority)

    /** Where a vehicle that is not parked should park, or `null` if nowhere. */
    fun forIdle(vehicle: Vehicle): String? {
        val candidates = freeFor(vehicle)
        vehicle.properties[DispatcherProperties.ASSIGNED_PARKING_POSITION]?.let { name ->
            return nearest(vehicle, candidates.filter { it.name == name })
        }
        vehicle.properties[DispatcherProperties.PREFERRED_PARKING_POSITION]?.let { name ->
            nearest(vehicle, candidates.filter { it.name == name })?.let { return it }
        }
        return if (run.configuration.considerParkingPositionPriorities) {
            nearestByPriority(vehicle, candidates)
        } else {
            nearest(vehicle, candidates)
        }
    }

    /** A free park point of higher priority than the one the vehicle is parked on, or `null`. */
    fun forRepark(vehicle: Vehicle): String? {
        val current = priority(vehicle.currentPosition) ?: Int.MAX_VALUE
        return nearestByPriority(vehicle, freeFor(vehicle).filter { (priority(it) ?: Int.MAX_VALUE) < current })
    }

    private fun priority(point: Point): Int? =
        point.properties[DispatcherProperties.PARKING_POSITION_PRIORITY]?.trim()?.toIntOrNull()

    private fun freeFor(vehicle: Vehicle): List<Point> =
        parkPoints.filter { it.name != vehicle.currentPosition && free.isFreeFor(it.name, vehicle) }

    private fun nearestByPriority(vehicle: Vehicle, points: List<Point>): String? = points
        .groupBy { priority(it) ?: Int.MAX_VALUE }
        .toSortedMap()
        .values
        .firstNotNullOfOrNull { nearest(vehicle, it) }

    private fun nearest(vehicle: Vehicle, points: List<Point>): String? = points
        .mapNotNull { point -> run.routes.costs(vehicle, point.name)?.let { point.name to it } }
        .minWithOrNull(compareBy({ it.second }, { it.first }))
        ?.first
}
