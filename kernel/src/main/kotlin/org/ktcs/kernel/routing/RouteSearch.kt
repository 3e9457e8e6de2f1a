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
 */
internal class RouteSearch(private val graph: RoutingGraph, private val algorithm: RoutingAlgorithm) {
    private val shortestPaths: ShortestPathAlgorithm<String, RoutingEdge> by lazy { algorithm.on(graph) }

    /** This search without [avoided]'s points and paths: a masked view of the same graph, built in constant time. */
    fun avoiding(avoided: AvoidedResources): RouteSearch = if (avoided.isEmpty()) {
        this
    } else {
        RouteSearch(MaskSubgraph(graph, { it in avoided.points }, { it.path in avoided.paths }), algorithm)
    }

    /**
     * The cheapest route from [source] to each of [targets] that can be reached; a target equal to [source] gets the
     * route that stays there. One single-source search, or a point-to-point one if there is a single target.
     */
    fun cheapestFrom(source: String, targets: Collection<String>): Map<String, Route> {
        val reachable = targets.filter { graph.containsVertex(it) }
        if (!graph.containsVertex(source) || reachable.isEmpty()) return emptyMap()
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
        count == 1 -> listOfNotNull(shortestPaths.getPath(source, target)?.toRoute())
        else -> YenKShortestPath(graph).getPaths(source, target, count).map { it.toRoute() }
    }
}

/** The route of a vehicle that is already where it should be: one step without a path, at no cost. */
internal fun routeStayingAt(point: String): Route =
    Route(listOf(Step(null, null, point, VehicleOrientation.UNDEFINED, 0)), 0)

private fun GraphPath<String, RoutingEdge>.toRoute(): Route = if (edgeList.isEmpty()) {
    routeStayingAt(startVertex)
} else {
    Route(edgeList.mapIndexed { index, edge -> edge.toStep(index) }, edgeList.sumOf { it.cost })
}

private fun RoutingAlgorithm.on(graph: RoutingGraph): ShortestPathAlgorithm<String, RoutingEdge> = when (this) {
    RoutingAlgorithm.DIJKSTRA -> DijkstraShortestPath(graph)
    RoutingAlgorithm.BELLMAN_FORD -> BellmanFordShortestPath(graph)
    RoutingAlgorithm.FLOYD_WARSHALL -> FloydWarshallShortestPaths(graph)
}
