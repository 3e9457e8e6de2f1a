package org.ktcs.kernel.routing

import org.ktcs.api.model.PlantModel

/** The transport order property listing, comma-separated, the points, paths and locations its routes must avoid. */
internal const val RESOURCES_TO_AVOID_PROPERTY = "tcs:resourcesToAvoid"

/** The points and paths, by name, that a route must not use. */
internal data class AvoidedResources(val points: Set<String>, val paths: Set<String>) {
    fun isEmpty(): Boolean = points.isEmpty() && paths.isEmpty()

    companion object {
        val NONE = AvoidedResources(emptySet(), emptySet())

        /**
         * What avoiding [names] means in [model]: a point or path is avoided itself, a location through all its linked
         * points (as in openTCS), and unknown names are ignored. The vehicle's [startPoint] is never avoided: it is
         * already there and has to leave. The work is proportional to [names] and their links, not to the model.
         */
        fun of(model: PlantModel, names: Collection<String>, startPoint: String): AvoidedResources {
            if (names.isEmpty()) return NONE
            val points = HashSet<String>()
            val paths = HashSet<String>()
            for (name in names) {
                when {
                    model.point(name) != null -> points += name
                    model.path(name) != null -> paths += name
                    else -> model.location(name)?.links?.forEach { points += it.point }
                }
            }
            points -= startPoint
            return AvoidedResources(points, paths)
        }
    }
}

/** The names in a `tcs:resourcesToAvoid` value, trimmed, without empty entries. */
internal fun parseResourceNames(value: String?): List<String> =
    value?.split(',')?.map { it.trim() }?.filter { it.isNotEmpty() }.orEmpty()
