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
            if (path.maxReverseVelocity > 0) {
                getOrPut(path.destinationPoint, ::ArrayList) += path.name to path.sourcePoint
            }
        }
    }
    private val points = model.points.mapTo(HashSet()) { it.name }
    private val locations = model.locations.mapTo(HashSet()) { it.name }
    private val twoWay: Set<String> = run {
        val directed = model.paths.filter { it.maxVelocity > 0 }.mapTo(HashSet()) {
            it.sourcePoint to
                it.destinationPoint
        }
        model.paths.filter { path ->
            (path.maxVelocity > 0 && path.maxReverseVelocity > 0) ||
                (path.destinationPoint to path.sourcePoint) in directed
        }.mapTo(HashSet()) { it.name }
    }

    /** Whether [path] may be driven in both directions (itself, or with a path the other way): vehicles may meet on it. */
    fun isTwoWay(path: String): Boolean = path in twoWay
    private val cache = HashMap<String, Exit>()

    fun isPoint(name: String): Boolean = name in points

    /**
     * Whether [point] is the end of a dead end: its only way out leads back to the one point it is reached from (a
     * park bay or station stub beside an aisle), not on to another (a detour bay beside a one-way lane).
     */
    fun isDeadEnd(point: String): Boolean {
        val out = exits[point].orEmpty().mapTo(HashSet()) { it.second }
        return out.size == 1 && exits[out.single()].orEmpty().any { it.second == point }
    }

    fun isLocation(name: String): Boolean = name in locations

    /**
     * What a vehicle standing at [point] needs to get away from it: the single-track corridor it must drive first
     * ([Exit.required]) and the ways on from the first point with a choice, of which it needs any one
     * ([Exit.options]).
     */
    fun from(point: String): Exit = cache.getOrPut(point) {
        val corridor = LinkedHashSet<String>()
        var current = point
        var previous: String? = null
        repeat(MAX_CORRIDOR) {
            // Turning back on a two-way track leads into the corridor just driven, never out of it.
            val ways = exits[current].orEmpty().filter { it.second != previous }
            val only = ways.singleOrNull()
            if (only == null || only.second == point) {
                return@getOrPut Exit(corridor, ways.map { (path, next) -> setOf(path, next) })
            }
            corridor += only.first
            corridor += only.second
            previous = current
            current = only.second
        }
        Exit(corridor, emptyList())
    }

    private companion object {
        /** Longer single-track corridors are unusual; the rest of one counts as a way out. */
        const val MAX_CORRIDOR = 64
    }
}

/** The way out of a point: a corridor to drive through, then any one of [options] (none: a dead end). */
internal class Exit(val required: Set<String>, val options: List<Set<String>>) {
    companion object {
        val NONE = Exit(emptySet(), emptyList())
    }
}
