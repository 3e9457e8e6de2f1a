package org.ktcs.kernel.core

import org.ktcs.api.model.PlantModel

/**
 * Where a vehicle of a deadlock can step aside when no reroute and no free park bay breaks it: the points up to
 * [MAX_HOPS] paths from where it stands, over points nobody holds, nearest first. Two vehicles head-on at the mouth of
 * a dead-end station stub (one in the aisle wants in, the other wants out) are broken that way: the one in the aisle
 * steps to an aisle point the other does not need, lets it out and comes back. The caller says which points are
 * taken (held, or needed by the other vehicles of the deadlock); the router then checks the way there and back.
 */
internal class SideSteps {
    private var model: PlantModel? = null
    private var next: Map<String, List<String>> = emptyMap()

    /** The free points near [from] in [layout], nearest first; [taken] points are neither passed nor offered. */
    fun near(layout: PlantModel, from: String, taken: (String) -> Boolean): List<String> {
        if (layout !== model) {
            next = successors(layout)
            model = layout
        }
        val found = ArrayList<String>()
        var frontier = listOf(from)
        val seen = hashSetOf(from)
        repeat(MAX_HOPS) {
            frontier = frontier.flatMap { next[it].orEmpty() }.filter { !taken(it) && seen.add(it) }
            found += frontier
        }
        return found
    }

    private fun successors(layout: PlantModel): Map<String, List<String>> {
        val next = HashMap<String, MutableList<String>>()
        for (path in layout.paths.filter { !it.locked }) {
            if (path.isNavigableForward) next.getOrPut(path.sourcePoint, ::ArrayList) += path.destinationPoint
            if (path.isNavigableReverse) next.getOrPut(path.destinationPoint, ::ArrayList) += path.sourcePoint
        }
        return next
    }

    private companion object {
        /** Far enough to clear a stub's mouth and the aisle point beside it, near enough to come back soon. */
        const val MAX_HOPS = 2
    }
}
