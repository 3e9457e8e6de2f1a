package org.ktcs.kernel.validation

import org.ktcs.api.model.PointType

/**
 * Plants where no traffic rule can keep vehicles moving: a dead end (a single track that leads nowhere else) with
 * more than one place to stop in it. Two vehicles sent to stops in the same dead end would have to pass each other
 * on the single track; the scheduler's deadlock avoidance can only keep the second one out while the first is in.
 */
internal fun trafficProblems(index: ModelIndex): List<ModelProblem> {
    val model = index.model
    val neighbours = HashMap<String, MutableSet<String>>()
    for (path in model.paths.filter { it.maxVelocity > 0 || it.maxReverseVelocity > 0 }) {
        neighbours.getOrPut(path.sourcePoint, ::HashSet) += path.destinationPoint
        neighbours.getOrPut(path.destinationPoint, ::HashSet) += path.sourcePoint
    }
    val linked = model.locations.flatMap { location -> location.links.map { it.point to location.name } }
        .groupBy({ it.first }, { it.second })
    fun stopsAt(point: String): List<String> = linked[point].orEmpty().map { "location '$it' at $point" } +
        listOfNotNull("park position $point".takeIf { model.point(point)?.type == PointType.PARK_POSITION })
    return model.points.filter { neighbours[it.name]?.size == 1 }.mapNotNull { end ->
        val corridor = deadEnd(end.name, neighbours)
        val stops = corridor.flatMap(::stopsAt)
        end.warningIf(stops.size > 1) {
            "dead end ${corridor.joinToString()} has ${stops.size} places to stop (${stops.joinToString()}): " +
                "vehicles sent to two of them must pass each other on one track, which no traffic rule can " +
                "arrange; a second vehicle waits outside until the first has left"
        }
    }
}

// From the dead end back along the single track, up to (not including) the first point with a choice.
private fun deadEnd(end: String, neighbours: Map<String, Set<String>>): List<String> {
    val corridor = mutableListOf(end)
    var previous = end
    var current = neighbours.getValue(end).single()
    while (neighbours[current]?.size == 2 && current !in corridor) {
        corridor += current
        val next = neighbours.getValue(current).first { it != previous }
        previous = current
        current = next
    }
    return corridor
}
