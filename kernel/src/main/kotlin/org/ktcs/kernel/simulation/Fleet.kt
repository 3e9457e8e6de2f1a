package org.ktcs.kernel.simulation

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.routing.pointsLinkedToLocations

/** Gives a model exactly [count] vehicles, each with an initial position of its own. */
object Fleet {
    const val INITIAL_POSITION = "loopback:initialPosition"

    fun withVehicles(model: PlantModel, count: Int): PlantModel {
        require(count >= 1) { "--vehicles must be at least 1, was $count" }
        val kept = model.vehicles.take(count)
        val added = (kept.size until count).map { Vehicle("Vehicle-%03d".format(it + 1)) }
        val taken = kept.mapNotNullTo(HashSet()) { it.properties[INITIAL_POSITION] }
        val free = startPoints(model).filter { it !in taken }.iterator()
        val vehicles = (kept + added).map { vehicle ->
            if (vehicle.properties[INITIAL_POSITION] != null) {
                vehicle
            } else {
                require(free.hasNext()) {
                    "plant '${model.name}' has no free point left for ${vehicle.name}; use fewer vehicles"
                }
                vehicle.copy(properties = vehicle.properties + (INITIAL_POSITION to free.next()))
            }
        }
        return model.copy(vehicles = vehicles)
    }

    // Park positions first, then points no station is linked to, so vehicles do not start in front of stations.
    private fun startPoints(model: PlantModel): List<String> {
        val linked = model.pointsLinkedToLocations()
        val (park, halt) = model.points.partition { it.type == PointType.PARK_POSITION }
        return park.map { it.name } + halt.map { it.name }.filter { it !in linked }
    }
}
