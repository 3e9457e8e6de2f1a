package org.ktcs.kernel.routing

import org.jgrapht.Graphs
import org.jgrapht.alg.connectivity.GabowStrongConnectivityInspector
import java.util.BitSet

/**
 * Which points can reach which in a routing graph, answered from its strongly connected components: all points of
 * one component reach each other, and a component reaches the components it reaches in the (acyclic) graph of
 * components. Components are found once per graph (that is, once per topology); what a component reaches is computed
 * on its first question and kept, so a routability check per order costs a few lookups, not a search of the plant.
 */
internal class Reachability(graph: RoutingGraph) {
    private val componentOf = HashMap<String, Int>()
    private val successors: List<IntArray>
    private val reached = HashMap<Int, BitSet>()

    init {
        val components = GabowStrongConnectivityInspector(graph).stronglyConnectedSets()
        components.forEachIndexed { index, points -> points.forEach { componentOf[it] = index } }
        successors = components.map { points ->
            points.asSequence()
                .flatMap { Graphs.successorListOf(graph, it) }
                .map { componentOf.getValue(it) }
                .toSortedSet().toIntArray()
        }
    }

    /** Whether [to] can be reached from [from] (a point always reaches itself); unknown points reach nothing. */
    fun reaches(from: String, to: String): Boolean {
        val source = componentOf[from] ?: return false
        val target = componentOf[to] ?: return false
        return reachedFrom(source)[target]
    }

    /** The points of [candidates] that some point of [starts] reaches. */
    fun reachedAmong(starts: Set<String>, candidates: List<String>): Set<String> {
        val sets = starts.mapNotNull { componentOf[it] }.distinct().map(::reachedFrom)
        return candidates.filterTo(HashSet()) { candidate ->
            val target = componentOf[candidate] ?: return@filterTo false
            sets.any { it[target] }
        }
    }

    fun contains(point: String): Boolean = point in componentOf

    private fun reachedFrom(component: Int): BitSet = reached.getOrPut(component) {
        val visited = BitSet()
        val queue = ArrayDeque<Int>()
        visited.set(component)
        queue.addLast(component)
        while (queue.isNotEmpty()) {
            for (next in successors[queue.removeFirst()]) {
                if (!visited[next]) {
                    visited.set(next)
                    queue.addLast(next)
                }
            }
        }
        visited
    }
}
