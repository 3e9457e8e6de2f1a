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
 * lets Floyd-Warshall compute its all-pairs table once per graph. With [RoutingAlgorithm.DIJKSTRA] (the default) and
 * no negative costs, the cheapest routes come from an [IndexedGraph] of the graph, built once and shared by the searches
 * that avoid resources: a search without a hash lookup per edge, a few hundred microseconds on a plant of thousands of
 * points.
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

    /** This search without [avoided]'s points and paths: a masked view of the same graph. */
    fun avoiding(avoided: AvoidedResources): RouteSearch = if (avoided.isEmpty()) {
        this
    } else {
        val masked = MaskSubgraph(graph, { it in avoided.points }, { it.path in avoided.paths })
        RouteSearch(masked, algorithm, indexed, indexed.value?.exclusion(avoided))
    }

    /**
     * The cheapest route from [source] to each of [targets] that can be reached; a target equal to [source] gets the
     * route that stays there. One single-source search, or a point-to-point one if there is a single target.
     */
    fun cheapestFrom(source: String, targets: Collection<String>): Map<String, Route> {
        val reachable = targets.filter { graph.containsVertex(it) }
        if (!graph.containsVertex(source) || reachable.isEmpty()) return emptyMap()
        val index = indexed.value ?: return cheapestWithAlgorithm(source, reachable)
        val targetIndices = reachable.map { checkNotNull(index.index(it)) }.toIntArray()
        val tree = index.search(checkNotNull(index.index(source)), exclusion, targetIndices)
        return reachable.zip(targetIndices.asList())
            .filter { (_, target) -> tree.reached(target) }
            .associate { (name, target) -> name to routeOf(name, tree.edgesTo(target)) }
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

    /** The cheapest costs from [source] to any point, from one single-source search made on first use. */
    fun costsFrom(source: String): (String) -> Long? {
        if (!graph.containsVertex(source)) return { null }
        val index = indexed.value
        if (index != null) {
            val tree by lazy(LazyThreadSafetyMode.NONE) { index.search(checkNotNull(index.index(source)), exclusion) }
            return { target ->
                val point = index.index(target)?.takeIf { graph.containsVertex(target) }
                when {
                    target == source -> 0L
                    point == null || !tree.reached(point) -> null
                    else -> tree.costs[point]
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

/** Up to [count] cheapest loop-free routes from [source] to [target], cheapest first. */
    fun cheapest(source: String, target: String, count: Int): List<Route> = when {
        !graph.containsVertex(source) || !graph.containsVertex(target) -> emptyList()
        source == target -> listOf(routeStayingAt(source))
        count == 1 -> cheapestFrom(source, listOf(target)).values.toList()
        else -> YenKShortestPath(graph).getPaths(source, target, count).map { it.toRoute() }
    }
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
