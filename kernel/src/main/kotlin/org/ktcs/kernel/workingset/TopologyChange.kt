package org.ktcs.kernel.workingset

import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle

/**
 * What a new model changes when it differs from the running plant only in what openTCS changes without restarting
 * vehicles: path locks, path velocities and location locks. [paths] and [locations] are the new versions of those
 * that changed.
 */
data class TopologyChange(val paths: List<Path>, val locations: List<Location>) {
    companion object {
        /**
         * The topology change from [running] (the plant as it runs, vehicles with their runtime state) to [model],
         * or null when [model] differs in anything else (then only replacing the whole plant applies it).
         */
        fun between(running: PlantModel, model: PlantModel): TopologyChange? {
            if (running.withoutTopology() != model.withoutTopology()) return null
            val runningPaths = running.paths.associateBy { it.name }
            val runningLocations = running.locations.associateBy { it.name }
            return TopologyChange(
                paths = model.paths.filter { it != runningPaths[it.name] },
                locations = model.locations.filter { it != runningLocations[it.name] },
            )
        }

        private fun PlantModel.withoutTopology() = copy(
            paths = paths.map { it.copy(locked = false, maxVelocity = 0, maxReverseVelocity = 0) },
            locations = locations.map { it.copy(locked = false) },
            vehicles = vehicles.map { it.asModelled() },
        )

        // A vehicle as a model file describes it, without what it reports at runtime (position, state, order, …).
        private fun Vehicle.asModelled() = Vehicle(
            name = name,
            energyLevelThresholdSet = energyLevelThresholdSet,
            maxVelocity = maxVelocity,
            maxReverseVelocity = maxReverseVelocity,
            boundingBox = boundingBox,
            envelopeKey = envelopeKey,
            layout = layout,
            properties = properties,
        )
    }
}
