package org.ktcs.kernel.routing

import org.ktcs.api.model.PlantModel

/** The points linked to a location: where vehicles stop to operate. */
internal fun PlantModel.pointsLinkedToLocations(): Set<String> =
    locations.flatMapTo(HashSet()) { location -> location.links.map { it.point } }
