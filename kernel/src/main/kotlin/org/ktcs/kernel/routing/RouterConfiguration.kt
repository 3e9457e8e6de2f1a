package org.ktcs.kernel.routing

/**
 * How [DefaultRouter] computes routes; the defaults are openTCS's (`defaultrouter.*`), except [routeComputationLimit].
 *
 * @property algorithm the shortest-path algorithm (`defaultrouter.shortestpath.algorithm`).
 * @property edgeEvaluators the cost functions whose results are added up per path direction
 *   (`defaultrouter.shortestpath.edgeEvaluators`); a direction any of them forbids is not routable.
 * @property explicitPropertiesDefaultValue the cost [EdgeEvaluator.EXPLICIT_PROPERTIES] gives a path direction without
 *   a cost property (`defaultrouter.edgeevaluator.explicitproperties.defaultValue`).
 * @property routeToCurrentPosition `false`: a drive order whose destination can be served at the point the vehicle
 *   starts from is served there, without comparing other candidate points: its route is one step without a path
 *   (`sourcePoint` and `path` null) at costs 0, so the vehicle performs the operation where it stands.
 *   `true`: that point is only one candidate among the others and the cheapest overall wins; it still costs 0, so the
 *   difference only shows with negative costs (see [RoutingAlgorithm.BELLMAN_FORD]). A route from a point to itself
 *   never drives a loop (`defaultrouter.routeToCurrentPosition`).
 * @property routeComputationLimit the most routes one [DefaultRouter.routes] call computes, however many it asks for
 *   (`defaultrouter.routeComputationLimit`). openTCS's default of 1 turns its multi-route query into a single-route
 *   one; kTCS honours requests up to this cap instead, which bounds the work of Yen's k-shortest-paths search.
 * @property operationPointSurcharge the percentage added to the cost of driving onto a point linked to a location
 *   (`router.operationPointSurcharge`; not in openTCS). Vehicles stop on such points to operate, and every vehicle
 *   behind waits, so a route that only passes through should go round them where the detour is short. A route to
 *   such a point pays the surcharge on its last path, whichever way it comes, so a route's costs include it. 0: off.
 */
data class RouterConfiguration(
    val algorithm: RoutingAlgorithm = RoutingAlgorithm.DIJKSTRA,
    val edgeEvaluators: List<EdgeEvaluator> = listOf(EdgeEvaluator.DISTANCE),
    val explicitPropertiesDefaultValue: Long = 1_000_000,
    val routeToCurrentPosition: Boolean = false,
    val routeComputationLimit: Int = DEFAULT_ROUTE_COMPUTATION_LIMIT,
    val operationPointSurcharge: Int = DEFAULT_OPERATION_POINT_SURCHARGE,
) {
    init {
        require(operationPointSurcharge >= 0) {
            "operationPointSurcharge must not be negative, was $operationPointSurcharge"
        }
        require(edgeEvaluators.isNotEmpty()) { "at least one edge evaluator is needed, got none" }
        require(routeComputationLimit >= 1) { "routeComputationLimit must be at least 1, was $routeComputationLimit" }
    }

    companion object {
        /** The default cap on routes per query: enough alternatives for a dispatcher, cheap for Yen's algorithm. */
        const val DEFAULT_ROUTE_COMPUTATION_LIMIT: Int = 10

        /**
         * 200: on the benchmark grids a 2 m path onto a station then costs like 6 m. Measured on 20x20 to 60x60 in
         * virtual time and through the web API against 0, 100, 300, 500 and 1000 (developer's guide, section 12).
         */
        const val DEFAULT_OPERATION_POINT_SURCHARGE: Int = 200
    }
}

/** The shortest-path algorithms of JGraphT the router can use. */
enum class RoutingAlgorithm {
    /** Dijkstra's algorithm: fast; costs must not be negative. */
    DIJKSTRA,

    /** Bellman-Ford: slower, but allows negative costs (from explicit cost properties) without negative cycles. */
    BELLMAN_FORD,

    /**
     * Floyd-Warshall: all pairs at once, cubic in the number of points, computed once per routing graph; a query with
     * resources to avoid computes its own table.
     */
    FLOYD_WARSHALL,
}

/** The cost functions for driving a path in one direction; the router adds up those configured. */
enum class EdgeEvaluator {
    /** The path's length in millimetres. */
    DISTANCE,

    /**
     * The expected driving time in milliseconds: length over the lower of the vehicle's and the path's maximum
     * velocity in the direction driven; forbidden when either is 0.
     */
    TRAVELTIME,

    /** 1 per path: the route with the fewest paths wins. */
    HOPS,

    /**
     * The path property `tcs:routingCostForward<GROUP>` or `tcs:routingCostReverse<GROUP>` for the vehicle's routing
     * group; `Infinity` forbids the direction and a missing property costs
     * [RouterConfiguration.explicitPropertiesDefaultValue].
     */
    EXPLICIT_PROPERTIES,

    /** 0, or forbidden when the vehicle's bounding box protrudes beyond the largest one the target point tolerates. */
    BOUNDING_BOX,
}
