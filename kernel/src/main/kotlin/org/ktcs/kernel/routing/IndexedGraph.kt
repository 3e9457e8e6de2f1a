package org.ktcs.kernel.routing

import org.jheaps.AddressableHeap
import org.jheaps.tree.PairingHeap
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
     * tree need. It breaks ties between routes of equal costs as JGraphT's `DijkstraShortestPath` does (same edge
     * order, same heap), so the router's choices do not change with the way it searches.
     */
    fun search(source: Int, excluded: Exclusion?): ShortestPathTree = ShortestPathTree(this, source, excluded)

    // The edges into point `p` are `incoming[firstIncoming[p] until firstIncoming[p + 1]]` (edge indices): made for the
    // first search backwards, which most graphs never get.
    private val firstIncoming: IntArray by lazy(LazyThreadSafetyMode.NONE) {
        val first = IntArray(size + 1)
        edgeTarget.forEach { first[it + 1]++ }
        for (point in 0 until size) first[point + 1] += first[point]
        first
    }
    private val incoming: IntArray by lazy(LazyThreadSafetyMode.NONE) {
        val next = firstIncoming.copyOf(size)
        val into = IntArray(edges.size)
        for (edge in edges.indices) into[next[edgeTarget[edge]]++] = edge
        into
    }

    /** Dijkstra's algorithm backwards from [target]: the costs of the cheapest routes from the other points to it. */
    fun searchTo(target: Int): CostsToTree = CostsToTree(this, target)

    /** Settles the cheapest point of [frontier] of a search backwards and offers the points with edges into it. */
    internal fun settlePrevious(tree: CostsToTree, frontier: Frontier) {
        val point = frontier.poll()
        val base = tree.costs[point]
        for (at in firstIncoming[point] until firstIncoming[point + 1]) {
            val edge = incoming[at]
            val source = edgeSource[edge]
            val cost = base + edgeCost[edge]
            if (frontier.offer(source, cost)) tree.costs[source] = cost
        }
    }

    /** Settles the cheapest point of [frontier] and offers its neighbours; returns it. */
    internal fun settleNext(tree: ShortestPathTree, frontier: Frontier, excluded: Exclusion?): Int {
        val point = frontier.poll()
        val base = tree.costs[point]
        for (edge in firstEdge[point] until firstEdge[point + 1]) {
            val target = edgeTarget[edge]
            if (excluded != null && (excluded.edges[edge] || excluded.points[target])) continue
            val cost = base + edgeCost[edge]
            if (frontier.offer(target, cost)) {
                tree.costs[target] = cost
                tree.viaEdge[target] = edge
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
    private var frontier: Frontier? = Frontier(graph.size)

    init {
        costs[source] = 0
        frontier?.offer(source, 0)
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
        val pending = frontier ?: return
        while (!pending.isSettled(point) && pending.isNotEmpty()) graph.settleNext(this, pending, excluded)
        // A drained frontier has settled all it can reach: its heap can go.
        if (!pending.isNotEmpty()) frontier = null
    }
}

/**
 * The points a search has reached but not settled, cheapest first: the pairing heap JGraphT's Dijkstra uses, fed in
 * the same order, so that points of equal costs come out in the same order as there (a binary heap, or any other
 * tie-break, picks other routes among equally cheap ones, and the vehicles' traffic changes with them).
 */
internal class Frontier(size: Int) {
    private val heap = PairingHeap<Long, Int>()
    private val handles = arrayOfNulls<AddressableHeap.Handle<Long, Int>>(size)
    private val settled = BitSet(size)

    fun isNotEmpty(): Boolean = !heap.isEmpty

    fun isSettled(point: Int): Boolean = settled[point]

    /** Offers [point] at [cost]; whether that is cheaper than it was offered before (always, the first time). */
    fun offer(point: Int, cost: Long): Boolean {
        // A settled point's costs cannot drop (no negative costs); its heap node is gone.
        if (settled[point]) return false
        val handle = handles[point]
        return when {
            handle == null -> {
                handles[point] = heap.insert(cost, point)
                true
            }

            cost < handle.key -> {
                handle.decreaseKey(cost)
                true
            }

            else -> false
        }
    }

    fun poll(): Int {
        val point = heap.deleteMin().value
        settled.set(point)
        handles[point] = null
        return point
    }
}
