package org.ktcs.kernel.routing

import org.jgrapht.GraphPath
import org.jgrapht.alg.interfaces.ShortestPathAlgorithm
import org.jgrapht.alg.shortestpath.BellmanFordShortestPath
import org.jgrapht.alg.shortestpath.DijkstraShortestPath
import org.jgrapht.alg.shortestpath.FloydWarshallShortestPaths
import org.jgrapht.alg.shortestpath.YenKShortestPath
import org.jgrapht.graph.MaskSubgraph
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.VehicleOrientation

/**
 * Shortest-path queries on one routing graph. The algorithm instance is created on first use and reused, which is what
 * lets Floyd-Warshall compute its all-pairs table once per graph.
 *
 * With [RoutingAlgorithm.DIJKSTRA] (the default) and no negative costs, the cheapest routes come from an
 * [IndexedGraph] of the graph (a search without a hash lookup per edge), and the search from each source point is
 * kept ([ShortestPathTree], resumed when a farther point is asked about) for the most recently used sources: the
 * graph never changes, so what a tree answered stays true until a new topology replaces this search. The dispatcher
 * asks the same questions again and again (from each station to the next one, from a vehicle to the orders it
 * chooses among), most of which are then answered by following a tree. Searches that avoid resources are not kept.
 */
internal class RouteSearch private constructor(
    private val graph: RoutingGraph,
    private val algorithm: RoutingAlgorithm,
    private val indexed: Lazy<IndexedGraph?>,
    private val exclusion: IndexedGraph.Exclusion?,
) {
    constructor(graph: RoutingGraph, algorithm: RoutingAlgorithm) : this(
        graph,
        algorithm,
        lazy(LazyThreadSafetyMode.NONE) {
            if (algorithm == RoutingAlgorithm.DIJKSTRA) IndexedGraph(graph).takeUnless { it.hasNegativeCosts } else null
        },
        exclusion = null,
    )

    private val shortestPaths: ShortestPathAlgorithm<String, RoutingEdge> by lazy { algorithm.on(graph) }
    private val keptTrees: Int by lazy(LazyThreadSafetyMode.NONE) {
        maxOf(MIN_KEPT_TREES, KEPT_TREE_POINTS / maxOf(1, indexed.value?.size ?: 1))
    }
    private val trees: MutableMap<Int, ShortestPathTree> by lazy(LazyThreadSafetyMode.NONE) { RecentTrees(keptTrees) }
    private val treesTo: MutableMap<Int, CostsToTree> by lazy(LazyThreadSafetyMode.NONE) { RecentTrees(keptTrees) }

    /** The search from [source] (a point of [index]): a kept one if nothing is avoided. */
    private fun treeFrom(index: IndexedGraph, source: String): ShortestPathTree {
        val point = checkNotNull(index.index(source))
        if (exclusion != null) return index.search(point, exclusion)
        return trees.getOrPut(point) { index.search(point, excluded = null) }
    }

    /** This search without [avoided]'s points and paths: a masked view of the same graph. */
    fun avoiding(avoided: AvoidedResources): RouteSearch = if (avoided.isEmpty()) {
        this
    } else {
        val masked = MaskSubgraph(graph, { it in avoided.points }, { it.path in avoided.paths })
        RouteSearch(masked, algorithm, indexed, indexed.value?.exclusion(avoided))
    }

    /**
     * The cheapest route from [source] to each of [targets] that can be reached; a target equal to [source] gets the
     * route that stays there. One single-source search (with the algorithm other than Dijkstra's: a point-to-point one
     * if there is a single target).
     */
    fun cheapestFrom(source: String, targets: Collection<String>): Map<String, Route> {
        val reachable = targets.filter { graph.containsVertex(it) }
        if (!graph.containsVertex(source) || reachable.isEmpty()) return emptyMap()
        val index = indexed.value ?: return cheapestWithAlgorithm(source, reachable)
        val tree = treeFrom(index, source)
        return reachable.mapNotNull { target ->
            tree.edgesTo(checkNotNull(index.index(target)))?.let { target to routeOf(target, it) }
        }.toMap()
    }

    private fun cheapestWithAlgorithm(source: String, reachable: List<String>): Map<String, Route> {
        val paths = if (reachable.size == 1) {
            listOfNotNull(shortestPaths.getPath(source, reachable.single()))
        } else {
            val tree = shortestPaths.getPaths(source)
            reachable.mapNotNull { tree.getPath(it) }
        }
        return paths.associate { it.endVertex to it.toRoute() }
    }

    /** The cheapest costs from [source] to any point, from one single-source search made as far as asked. */
    fun costsFrom(source: String): (String) -> Long? {
        if (!graph.containsVertex(source)) return { null }
        val index = indexed.value
        if (index != null) {
            val tree by lazy(LazyThreadSafetyMode.NONE) { treeFrom(index, source) }
            return { target ->
                when {
                    target == source -> 0L
                    !graph.containsVertex(target) -> null
                    else -> index.index(target)?.let(tree::costsTo)
                }
            }
        }
        val tree by lazy { shortestPaths.getPaths(source) }
        return { target ->
            when {
                target == source -> 0L
                !graph.containsVertex(target) -> null
                else -> tree.getWeight(target).takeIf { it.isFinite() }?.toLong()
            }
        }
    }

    /**
     * The cheapest costs from any point to [target]: with Dijkstra's algorithm one search backwards, kept for the most
     * recently asked targets as the searches forwards are; otherwise one search from each point asked about.
     */
    fun costsTo(target: String): (String) -> Long? {
        if (!graph.containsVertex(target)) return { null }
        val index = indexed.value?.takeIf { exclusion == null } ?: return { source -> costsFrom(source)(target) }
        val point = checkNotNull(index.index(target))
        val tree by lazy(LazyThreadSafetyMode.NONE) { treesTo.getOrPut(point) { index.searchTo(point) } }
        return { source ->
            when {
                source == target -> 0L
                !graph.containsVertex(source) -> null
                else -> index.index(source)?.let(tree::costsFrom)
            }
        }
    }

    /** Up to [count] cheapest loop-free routes from [source] to [target], cheapest first. */
    fun cheapest(source: String, target: String, count: Int): List<Route> = when {
        !graph.containsVertex(source) || !graph.containsVertex(target) -> emptyList()
        source == target -> listOf(routeStayingAt(source))
        count == 1 -> cheapestFrom(source, listOf(target)).values.toList()
        else -> YenKShortestPath(graph).getPaths(source, target, count).map { it.toRoute() }
    }
}

/** The searches kept per routing graph: at least this many, */
private const val MIN_KEPT_TREES = 16

/** and as many as hold this many points in all (12 bytes a point, and an unfinished search's frontier: about 6 MB). */
private const val KEPT_TREE_POINTS = 500_000

/** The [capacity] most recently used searches by source point (by target point, backwards), in access order. */
private class RecentTrees<T>(private val capacity: Int) : LinkedHashMap<Int, T>(capacity, 0.75f, true) {
    override fun removeEldestEntry(eldest: MutableMap.MutableEntry<Int, T>): Boolean = size > capacity
}

/** The route of a vehicle that is already where it should be: one step without a path, at no cost. */
internal fun routeStayingAt(point: String): Route =
    Route(listOf(Step(null, null, point, VehicleOrientation.UNDEFINED, 0)), 0)

private fun GraphPath<String, RoutingEdge>.toRoute(): Route = routeOf(startVertex, edgeList)

/** The route along [edges], or the one staying at [start] if there are none. */
private fun routeOf(start: String, edges: List<RoutingEdge>): Route = if (edges.isEmpty()) {
    routeStayingAt(start)
} else {
    Route(edges.mapIndexed { index, edge -> edge.toStep(index) }, edges.sumOf { it.cost })
}

private fun RoutingAlgorithm.on(graph: RoutingGraph): ShortestPathAlgorithm<String, RoutingEdge> = when (this) {
    RoutingAlgorithm.DIJKSTRA -> DijkstraShortestPath(graph)
    RoutingAlgorithm.BELLMAN_FORD -> BellmanFordShortestPath(graph)
    RoutingAlgorithm.FLOYD_WARSHALL -> FloydWarshallShortestPaths(graph)
}
