package org.ktcs.kernel.scheduling

import org.ktcs.api.model.PlantModel

/**
 * The way out of each point: what a vehicle that stops there needs in order to leave again. From the point it
 * follows the only drivable path as long as there is only one (a dead-end stub, a park bay, a one-way corridor) and
 * then takes every way out of the first point with a choice. Built once per model; locks are ignored, as a locked
 * path may be unlocked while the vehicle stands.
 */
internal class ExitCorridors(model: PlantModel) {
    private val exits: Map<String, List<Pair<String, String>>> = buildMap<String, MutableList<Pair<String, String>>> {
        for (path in model.paths) {
            if (path.maxVelocity > 0) getOrPut(path.sourcePoint, ::ArrayList) += path.name to path.destinationPoint
            if (path.maxReverseVelocity > 0) getOrPut(path.destinationPoint, ::ArrayList) += path.name to path.sourcePoint
        }
    }
    private val points = model.points.mapTo(HashSet()) { it.name }
    private val twoWay: Set<String> = run {
        val directed = model.paths.filter { it.maxVelocity > 0 }.mapTo(HashSet()) { it.sourcePoint to it.destinationPoint }
        model.paths.filter { path ->
            (path.maxVelocity > 0 && path.maxReverseVelocity > 0) ||
                (path.destinationPoint to path.sourcePoint) in directed
        }.mapTo(HashSet()) { it.name }
    }

    /** Whether [path] may be driven in both directions (itself, or with a path the other way): vehicles may meet on it. */
    fun isTwoWay(path: String): Boolean = path in twoWay
    private val cache = HashMap<String, Set<String>>()

    fun isPoint(name: String): Boolean = name in points

    /** The paths and points a vehicle standing at [point] needs to get away from it. */
    fun from(point: String): Set<String> = cache.getOrPut(point) {
        val corridor = LinkedHashSet<String>()
        var current = point
        repeat(MAX_CORRIDOR) {
            val ways = exits[current].orEmpty()
            ways.forEach { (path, next) ->
                corridor += path
                corridor += next
            }
            val only = ways.singleOrNull() ?: return@getOrPut corridor
            if (only.second == point) return@getOrPut corridor
            current = only.second
        }
        corridor
    }

    private companion object {
        /** Longer single-track corridors are unusual; the rest of one counts as a way out. */
        const val MAX_CORRIDOR = 64
    }
}
