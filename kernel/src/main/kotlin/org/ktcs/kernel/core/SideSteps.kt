package org.ktcs.kernel.core

import org.ktcs.api.model.BlockType
import org.ktcs.api.model.PlantModel

/**
 * Where a vehicle of a deadlock can step aside when no reroute and no free park bay breaks it: the points up to
 * [MAX_HOPS] paths from where it stands, over points nobody holds, nearest first, that the other vehicles of the
 * deadlock do not need. Two vehicles head-on at the mouth of a dead-end station stub (one in the aisle wants in, the
 * other wants out) are broken that way: the one in the aisle steps to an aisle point the other does not need, lets it
 * out and comes back. Two vehicles head-on inside an aisle, or at its end, need more: one backs off along the other's
 * way (points the other needs but nobody holds may be passed, not stopped on) into a stub or a cross aisle beyond it.
 * Points of a SINGLE_VEHICLE_ONLY block are passed, not offered: a vehicle standing on one holds the whole block, in
 * the way of every vehicle crossing it. The caller says which points are held and which are needed; the router then
 * checks the way there and back.
 */
internal class SideSteps {
    private var model: PlantModel? = null
    private var next: Map<String, List<String>> = emptyMap()
    private var inSingleBlock: Set<String> = emptySet()

    /**
     * The free points near [from] in [layout], nearest first: [held] points are neither passed nor offered, [needed]
     * ones are passed but not offered.
     */
    fun near(
        layout: PlantModel,
        from: String,
        held: (String) -> Boolean,
        needed: (String) -> Boolean = { false },
    ): List<String> {
        if (layout !== model) {
            next = successors(layout)
            inSingleBlock = layout.blocks.filter { it.type == BlockType.SINGLE_VEHICLE_ONLY }.flatMapTo(HashSet()) {
                it.members
            }
            model = layout
        }
        val found = ArrayList<String>()
        var frontier = listOf(from)
        val seen = hashSetOf(from)
        repeat(MAX_HOPS) {
            frontier = frontier.flatMap { next[it].orEmpty() }.filter { !held(it) && seen.add(it) }
            frontier.filterTo(found) { !needed(it) && it !in inSingleBlock }
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
        /**
         * Far enough to back off past the next stub or out of an aisle's end onto a cross aisle, near enough to come
         * back soon (the nearest point is offered first).
         */
        const val MAX_HOPS = 4
    }
}
