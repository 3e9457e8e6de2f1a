package org.ktcs.kernel.routing

import org.jgrapht.Graphs
import org.jgrapht.graph.MaskSubgraph

/**
 * Whether some point of each leg can be reached from a reachable point of the leg before, in [graph]. The first leg
 * has no start, so any of its points will do. A leg without points makes the whole order unroutable.
 */
internal fun isRoutableInPrinciple(graph: RoutingGraph, legCandidates: List<List<String>>): Boolean {
    var reached: Set<String> = legCandidates.firstOrNull()?.filterTo(HashSet()) { graph.containsVertex(it) }
        ?: return true
    for (candidates in legCandidates.drop(1)) {
        if (reached.isEmpty()) return false
        val reachable = graph.reachableFrom(reached)
        reached = candidates.filterTo(HashSet()) { it in reachable }
    }
    return reached.isNotEmpty()
}

/** Every vertex reachable from [starts], [starts] included: a breadth-first search. */
private fun RoutingGraph.reachableFrom(starts: Set<String>): Set<String> {
    val visited = HashSet(starts)
    val queue = ArrayDeque(starts)
    while (queue.isNotEmpty()) {
        for (next in Graphs.successorListOf(this, queue.removeFirst())) {
            if (visited.add(next)) queue.addLast(next)
        }
    }
    return visited
}

/** This graph without the points and paths of [avoided]; a view, not a copy. */
internal fun RoutingGraph.without(avoided: AvoidedResources): RoutingGraph =
    if (avoided.isEmpty()) this else MaskSubgraph(this, { it in avoided.points }, { it.path in avoided.paths })
