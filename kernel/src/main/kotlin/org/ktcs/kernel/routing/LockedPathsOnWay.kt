package org.ktcs.kernel.routing

import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.TransportOrder

/**
 * The locked paths that stand between [source] and the destinations of [order]: those on the way with the fewest
 * paths that the plant would offer if no path were locked. Empty if there is no such way (the plant itself does not
 * connect them) or if nothing on it is locked. Explains a missing route to operators; it runs only when routing failed.
 */
internal fun PlantModel.lockedPathsOnWay(source: String, order: TransportOrder): List<String> {
    val outgoing = outgoingEdges()
    var from = source
    val locked = LinkedHashSet<String>()
    for (driveOrder in order.driveOrders) {
        val targets = destinationPoints(driveOrder.destination, includeLockedLocations = true).toSet()
        val way = fewestPaths(outgoing, from, targets) ?: return emptyList()
        way.paths.filter(Path::locked).mapTo(locked, Path::name)
        from = way.end
    }
    return locked.toList()
}

/** The locked paths between [source] and [target], as [lockedPathsOnWay] finds them. */
internal fun PlantModel.lockedPathsBetween(source: String, target: String): List<String> =
    fewestPaths(outgoingEdges(), source, setOf(target))?.paths?.filter(Path::locked)?.map(Path::name).orEmpty()

private class Edge(val path: Path, val to: String)

private class Way(val end: String, val paths: List<Path>)

private fun PlantModel.outgoingEdges(): Map<String, List<Edge>> {
    val edges = HashMap<String, MutableList<Edge>>()
    for (path in paths) {
        if (path.isNavigableForward) {
            edges.getOrPut(path.sourcePoint, ::ArrayList).add(Edge(path, path.destinationPoint))
        }
        if (path.isNavigableReverse) {
            edges.getOrPut(path.destinationPoint, ::ArrayList).add(Edge(path, path.sourcePoint))
        }
    }
    return edges
}

/** Breadth-first: the way with the fewest paths from [source] to any of [targets], locks ignored. */
private fun fewestPaths(outgoing: Map<String, List<Edge>>, source: String, targets: Set<String>): Way? {
    if (source in targets) return Way(source, emptyList())
    val reachedBy = HashMap<String, Edge?>().apply { put(source, null) }
    val queue = ArrayDeque(listOf(source))
    while (queue.isNotEmpty()) {
        val point = queue.removeFirst()
        for (edge in outgoing[point].orEmpty()) {
            if (edge.to in reachedBy) continue
            reachedBy[edge.to] = edge
            if (edge.to in targets) return Way(edge.to, backtrack(reachedBy, edge.to))
            queue.addLast(edge.to)
        }
    }
    return null
}

private fun backtrack(reachedBy: Map<String, Edge?>, end: String): List<Path> {
    val way = ArrayList<Path>()
    var point = end
    while (true) {
        val edge = reachedBy[point] ?: break
        way.add(edge.path)
        point = if (edge.to == edge.path.destinationPoint) edge.path.sourcePoint else edge.path.destinationPoint
    }
    way.reverse()
    return way
}
