package org.ktcs.kernel.validation

import org.ktcs.api.model.PlantModel

/** Lookups the checks share, built once per validation so that each check stays linear in the size of the model. */
internal class ModelIndex(val model: PlantModel) {
    val layerIds: Set<Int> = model.visualLayout.layers.mapTo(HashSet()) { it.id }
    val layerGroupIds: Set<Int> = model.visualLayout.layerGroups.mapTo(HashSet()) { it.id }
    val usedLocationTypes: Set<String> = model.locations.mapTo(HashSet()) { it.type }
    val envelopeKeys: Set<String> = envelopeMaps(model).flatMapTo(HashSet()) { it.keys }
    val peripheralLocations: Set<String> =
        model.paths.flatMapTo(HashSet()) { path -> path.peripheralOperations.map { it.location } }

    /** Whether [name] is something a block may contain: a point, a path or a location. */
    fun isBlockable(name: String): Boolean =
        model.point(name) != null || model.path(name) != null || model.location(name) != null
}

private fun envelopeMaps(model: PlantModel): List<Map<String, *>> =
    model.points.map { it.vehicleEnvelopes } + model.paths.map { it.vehicleEnvelopes }
