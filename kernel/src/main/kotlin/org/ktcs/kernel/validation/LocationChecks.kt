package org.ktcs.kernel.validation

import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.PlantModel

internal fun locationProblems(index: ModelIndex): List<ModelProblem> =
    index.model.locations.flatMap { locationProblems(it, index) }

internal fun locationTypeProblems(index: ModelIndex): List<ModelProblem> =
    index.model.locationTypes.mapNotNull { type ->
        type.warningIf(type.name !in index.usedLocationTypes) { "is used by no location" }
    }

private fun locationProblems(location: Location, index: ModelIndex): List<ModelProblem> {
    val type = index.model.locationType(location.type)
    return listOfNotNull(
        location.errorIf(type == null) { "location type '${location.type}' does not exist" },
        unreachable(location, index),
    ) + location.links.flatMap { linkProblems(location, it, type, index.model) }
}

/** Peripheral devices such as fire doors are operated from paths, so they need no links. */
private fun unreachable(location: Location, index: ModelIndex): ModelProblem? =
    location.warningIf(location.links.isEmpty() && location.name !in index.peripheralLocations) {
        "is unreachable: it has no links to points"
    }

private fun linkProblems(location: Location, link: Link, type: LocationType?, model: PlantModel): List<ModelProblem> =
    listOfNotNull(
        location.errorIf(model.point(link.point) == null) { "link to unknown point '${link.point}'" },
        type?.let { disallowedOperations(location, link, it) },
    )

/** openTCS lets a link narrow its location type's operations, never widen them. */
private fun disallowedOperations(location: Location, link: Link, type: LocationType): ModelProblem? {
    val extra = link.allowedOperations - type.allowedOperations
    return location.errorIf(extra.isNotEmpty()) {
        "link to point '${link.point}' allows operations ${extra.sorted()} " +
            "that location type '${type.name}' does not allow"
    }
}
