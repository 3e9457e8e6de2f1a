package org.ktcs.kernel.routing

import org.jgrapht.graph.MaskSubgraph

/**
 * Whether some point of each leg can be reached from a reachable point of the leg before, in the graph [reachability]
 * describes. The first leg has no start, so any of its points will do. A leg without points makes the whole order
 * unroutable.
 */
internal fun isRoutableInPrinciple(reachability: Reachability, legCandidates: List<List<String>>): Boolean {
    var reached: Set<String> = legCandidates.firstOrNull()?.filterTo(HashSet()) { reachability.contains(it) }
        ?: return true
    for (candidates in legCandidates.drop(1)) {
        if (reached.isEmpty()) return false
        reached = reachability.reachedAmong(reached, candidates)
    }
    return reached.isNotEmpty()
}

/** This graph without the points and paths of [avoided]; a view, not a copy. */
internal fun RoutingGraph.without(avoided: AvoidedResources): RoutingGraph =
    if (avoided.isEmpty()) this else MaskSubgraph(this, { it in avoided.points }, { it.path in avoided.paths })
