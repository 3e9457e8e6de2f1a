package org.ktcs.kernel.routing

import org.ktcs.api.order.Route

/**
 * Chooses one point per leg of a transport order so that the whole trip is cheapest, by dynamic programming over the
 * legs: for each candidate point of a leg it keeps only the cheapest way to get there, so the work grows with the sum,
 * not the product, of the legs' candidate counts (one single-source search per kept point and leg).
 *
 * @param stayWhenPossible a leg whose candidates include the point the vehicle is at ends there without comparing the
 *   others ([RouterConfiguration.routeToCurrentPosition] `false`).
 */
internal class CheapestOrderRoute(private val search: RouteSearch, private val stayWhenPossible: Boolean) {
    /** One route per leg, from [sourcePoint] through a point of each of [legCandidates]; `null` if there is none. */
    fun compute(sourcePoint: String, legCandidates: List<List<String>>): List<Route>? {
        var arrivals = listOf(Arrival(sourcePoint, 0, route = null, previous = null))
        for (candidates in legCandidates) {
            arrivals = nextArrivals(arrivals, candidates)
            if (arrivals.isEmpty()) return null
        }
        val cheapest = arrivals.minBy { it.totalCost }
        return generateSequence(cheapest) { it.previous }.mapNotNull { it.route }.toList().asReversed()
    }

    private fun nextArrivals(arrivals: List<Arrival>, candidates: List<String>): List<Arrival> {
        val cheapestPerPoint = LinkedHashMap<String, Arrival>()
        for (from in arrivals) {
            for ((point, route) in legRoutes(from.point, candidates)) {
                val arrival = Arrival(point, from.totalCost + route.costs, route, from)
                val known = cheapestPerPoint[point]
                if (known == null || arrival.totalCost < known.totalCost) cheapestPerPoint[point] = arrival
            }
        }
        return cheapestPerPoint.values.toList()
    }

    private fun legRoutes(from: String, candidates: List<String>): Map<String, Route> =
        if (stayWhenPossible && from in candidates) {
            mapOf(from to routeStayingAt(from))
        } else {
            search.cheapestFrom(from, candidates)
        }

    /** The cheapest known way to stand at [point] after a leg; [route] is that leg's, `null` before the first leg. */
    private class Arrival(val point: String, val totalCost: Long, val route: Route?, val previous: Arrival?)
}
