package org.ktcs.kernel.routing

import org.ktcs.api.model.Link
import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations

/**
 * The points at which a vehicle can carry out [destination], in link order: a point target is itself; a location
 * target offers each linked point whose link permits the operation. A link without operations of its own permits
 * those of the location type, and [Operations.NOP] is permitted everywhere. A locked location offers no point unless
 * [includeLockedLocations]; an unknown target offers none.
 */
internal fun PlantModel.destinationPoints(destination: Destination, includeLockedLocations: Boolean): List<String> {
    if (point(destination.target) != null) return listOf(destination.target)
    val location = location(destination.target) ?: return emptyList()
    if (location.locked && !includeLockedLocations) return emptyList()
    val typeOperations = locationType(location.type)?.allowedOperations.orEmpty()
    return location.links
        .filter { it.permits(destination.operation, typeOperations) }
        .map(Link::point)
        .distinct()
}

private fun Link.permits(operation: String, typeOperations: Set<String>): Boolean = when {
    operation == Operations.NOP -> true
    allowedOperations.isEmpty() -> operation in typeOperations
    else -> operation in allowedOperations
}
