package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle

/**
 * Chooses a start point for loopback vehicles whose model gives none (openTCS's plant files never do: there the
 * operator sets it in the loopback panel). A vehicle gets the first free park position, else the first free point, in
 * the model's order; free means no vehicle stands there, none starts there by its
 * [LoopbackProperties.INITIAL_POSITION] and no other vehicle was placed there. Shared by the drivers of one factory,
 * so vehicles enabled one after another never get the same point. Confined to the kernel context.
 */
class Placement {
    private val placed = HashMap<String, String>()

    /** The point for [vehicle], or `null` if every point is taken; remembers it for the other vehicles. */
    fun startPoint(vehicle: Vehicle, context: DriverContext): Point? {
        val model = context.plantModel
        val standing = context.vehiclePositions() - vehicle.name
        val taken = HashSet<String>(standing.values)
        placed.forEach { (name, point) -> if (name != vehicle.name && name !in standing) taken += point }
        model.vehicles.forEach { other ->
            if (other.name != vehicle.name) other.properties[LoopbackProperties.INITIAL_POSITION]?.let(taken::add)
        }
        val free = model.points.filter { it.name !in taken }
        val point = free.firstOrNull { it.type == PointType.PARK_POSITION } ?: free.firstOrNull() ?: return null
        placed[vehicle.name] = point.name
        return point
    }

    /** What the operator reads (the kernel logs notifications too): where the vehicle went and how to keep it there. */
    fun announce(vehicle: Vehicle, point: Point): String {
        val kind = if (point.type == PointType.PARK_POSITION) "park position" else "point"
        val text = "${vehicle.name} had no position; placed it on the free $kind ${point.name}. Pin it with the " +
            "vehicle property ${LoopbackProperties.INITIAL_POSITION}=${point.name}, or move it in the overview's " +
            "loopback panel (loopback.placeUnpositionedVehicles=false leaves it unplaced)."
        return text
    }
}
