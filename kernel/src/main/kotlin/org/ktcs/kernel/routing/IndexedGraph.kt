package org.ktcs.kernel.routing

import org.ktcs.kernel.routing.IndexedGraph.Exclusion
import java.util.BitSet

/**
 * A routing graph in arrays, for Dijkstra's algorithm without a hash lookup per edge: points are numbered, and each
 * point's outgoing edges lie side by side (compressed sparse rows). Built once per routing graph, on its first search;
 * the routing graph itself never changes (a new topology makes new graphs), so neither does this.
 */
internal class IndexedGraph(graph: RoutingGraph) {
    private val names: Array<String> = graph.vertexSet().toTypedArray()
    private val indexOf: Map<String, Int> = names.withIndex().associate { (index, name) -> name to index }

    /** The outgoing edges of point `p` are `edges[firstEdge[p] until firstEdge[p + 1]]`. */
    private val firstEdge = IntArray(names.size + 1)
    val edges: Array<RoutingEdge>
    val edgeSource: IntArray
    private val edgeTarget: IntArray
    private val edgeCost: LongArray
    private val edgesOfPath: Map<String, IntArray>

    init {
        val outgoing = names.map { graph.outgoingEdgesOf(it).toList() }
        outgoing.forEachIndexed { point, list -> firstEdge[point + 1] = firstEdge[point] + list.size }
        edges = outgoing.flatten().toTypedArray()
        edgeSource = IntArray(edges.size) { indexOf.getValue(edges[it].source) }
        edgeTarget = IntArray(edges.size) { indexOf.getValue(edges[it].target) }
        edgeCost = LongArray(edges.size) { edges[it].cost }
        edgesOfPath = edges.indices.groupBy { edges[it].path }.mapValues { it.value.toIntArray() }
    }

    val size: Int get() = names.size

    /** Whether an edge costs less than nothing, which Dijkstra's algorithm cannot handle. */
    val hasNegativeCosts: Boolean = edgeCost.any { it < 0 }

    fun index(point: String): Int? = indexOf[point]

    fun name(index: Int): String = names[index]

    /** The points and edges [avoided] excludes from this graph, for [search]; `null` if it excludes nothing. */
    fun exclusion(avoided: AvoidedResources): Exclusion? {
        if (avoided.isEmpty()) return null
        val points = BitSet(size)
        avoided.points.forEach { point -> index(point)?.let(points::set) }
        val edgeSet = BitSet(edges.size)
        avoided.paths.forEach { path -> edgesOfPath[path]?.forEach(edgeSet::set) }
        return Exclusion(points, edgeSet)
    }

    /** Points and edges, by index, that a search must not use. */
    class Exclusion(val points: BitSet, val edges: BitSet)

    /**
     * Dijkstra's algorithm from [source] around [excluded], settling points only as far as the questions asked of the
     * tree need. Ties are broken by point index, so a tree answers every question as a complete search would.
     */
    fun search(source: Int, excluded: Exclusion?): ShortestPathTree = ShortestPathTree(this, source, excluded)

    /** Settles the cheapest point of [queue] and offers its neighbours; returns it. */
    internal fun settleNext(tree: ShortestPathTree, queue: PointQueue, excluded: Exclusion?): Int {
        val point = queue.poll()
        val base = tree.costs[point]
        for (edge in firstEdge[point] until firstEdge[point + 1]) {
            val target = edgeTarget[edge]
            if (excluded != null && (excluded.edges[edge] || excluded.points[target])) continue
            val cost = base + edgeCost[edge]
            if (cost < tree.costs[target]) {
                tree.costs[target] = cost
                tree.viaEdge[target] = edge
                queue.offer(target)
            }
        }
        return point
    }
}

/**
 * The cheapest routes from one point ([source]): a search that goes on only as far as the points asked about
 * ([costsTo], [edgesTo]), so a question about a near point costs a search of the neighbourhood, and a later question
 * about a farther one resumes it. What it answered stays true: the graph never changes.
 */
internal class ShortestPathTree(private val graph: IndexedGraph, val source: Int, private val excluded: Exclusion?) {
    val costs = LongArray(graph.size) { Long.MAX_VALUE }
    val viaEdge = IntArray(graph.size) { -1 }
    private var queue: PointQueue? = PointQueue(graph.size, costs)

    init {
        costs[source] = 0
        queue?.offer(source)
    }

    /** The costs of the cheapest route to [point], or `null` if it cannot be reached. */
    fun costsTo(point: Int): Long? {
        settle(point)
        return costs[point].takeIf { it != Long.MAX_VALUE }
    }

    /** The edges of the cheapest route to [point] in driving order (empty for the source), or `null` if none. */
    fun edgesTo(point: Int): List<RoutingEdge>? {
        costsTo(point) ?: return null
        val reversed = ArrayList<RoutingEdge>()
        var at = point
        while (at != source) {
            val edge = viaEdge[at]
            reversed += graph.edges[edge]
            at = graph.edgeSource[edge]
        }
        return reversed.asReversed()
    }

    private fun settle(point: Int) {
        val pending = queue ?: return
        while (!pending.isSettled(point) && pending.isNotEmpty()) graph.settleNext(this, pending, excluded)
        // A drained queue has settled all it can reach: its arrays can go.
        if (!pending.isNotEmpty()) queue = null
    }
}

/**
 * A binary min-heap of point indices ordered by their costs (then by index), with decrease-key: a point offered
 * again after its costs dropped moves up instead of being queued twice.
 */
internal class PointQueue(size: Int, private val costs: LongArray) {
    private val heap = IntArray(size)
    private val position = IntArray(size) { -1 }
    private var count = 0

    fun isNotEmpty(): Boolean = count > 0

    fun isSettled(point: Int): Boolean = position[point] == SETTLED

    fun offer(point: Int) {
        if (position[point] == SETTLED) return
        if (position[point] < 0) {
            heap[count] = point
            position[point] = count
            count++
        }
        siftUp(position[point])
    }

    fun poll(): Int {
        val first = heap[0]
        position[first] = SETTLED
        count--
        if (count > 0) {
            place(heap[count], 0)
            siftDown(0)
        }
        return first
    }

    private fun siftUp(start: Int) {
        var at = start
        val point = heap[at]
        while (at > 0) {
            val parent = (at - 1) / 2
            if (!before(point, heap[parent])) break
            place(heap[parent], at)
            at = parent
        }
        place(point, at)
    }

    private fun siftDown(start: Int) {
        var at = start
        val point = heap[at]
        while (true) {
            var child = 2 * at + 1
            if (child >= count) break
            if (child + 1 < count && before(heap[child + 1], heap[child])) child++
            if (!before(heap[child], point)) break
            place(heap[child], at)
            at = child
        }
        place(point, at)
    }

    private fun place(point: Int, at: Int) {
        heap[at] = point
        position[point] = at
    }

    private fun before(a: Int, b: Int): Boolean = costs[a] < costs[b] || (costs[a] == costs[b] && a < b)

    private companion object {
        const val SETTLED = -2
    }
}
