package org.ktcs.kernel.dispatching

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.routing.Router
import java.util.PriorityQueue

/**
 * A small, obviously correct router for dispatcher tests: Dijkstra over path lengths, locked paths left out, a
 * location reached through its cheapest link that allows the operation. Counts the calls the dispatcher makes.
 */
class FakeRouter(private val model: () -> PlantModel) : Router {
    var routeOrderCalls = 0
        private set
    var routesCalls = 0
        private set

    override fun updateTopology(model: PlantModel) {}

    override fun isGenerallyRoutable(order: TransportOrder): Boolean = true

    override fun routeOrder(vehicle: Vehicle, sourcePoint: String, order: TransportOrder): List<DriveOrder>? {
        routeOrderCalls++
        val avoid = order.properties[DispatcherProperties.RESOURCES_TO_AVOID]?.split(",")?.toSet().orEmpty()
        var source = sourcePoint
        return order.driveOrders.map { driveOrder ->
            val route = accessPoints(driveOrder).mapNotNull { shortest(source, it, avoid) }.minByOrNull { it.costs }
                ?: return null
            source = route.finalDestinationPoint!!
            driveOrder.copy(route = route)
        }
    }

    override fun routes(
        vehicle: Vehicle,
        sourcePoint: String,
        destinationPoint: String,
        resourcesToAvoid: Set<String>,
        maxRoutes: Int,
    ): List<Route> {
        routesCalls++
        return listOfNotNull(shortest(sourcePoint, destinationPoint, resourcesToAvoid))
    }

    private fun accessPoints(driveOrder: DriveOrder): List<String> {
        val target = driveOrder.destination.target
        val location = model().location(target) ?: return listOf(target)
        val operation = driveOrder.destination.operation
        return location.links.filter {
            it.allowedOperations.isEmpty() || operation in it.allowedOperations
        }.map { it.point }
    }

    private fun shortest(from: String, to: String, avoid: Set<String>): Route? {
        if (from == to) return Route(listOf(Step(null, null, to)), 0)
        val edges = edges(avoid)
        val best = HashMap<String, Pair<Long, List<Step>>>().apply { put(from, 0L to emptyList()) }
        val queue = PriorityQueue<Pair<String, Long>>(compareBy { it.second }).apply { add(from to 0L) }
        while (queue.isNotEmpty()) {
            val (point, costs) = queue.poll()
            if (costs > best.getValue(point).first) continue
            if (point == to) return best.getValue(point).let { Route(it.second, it.first) }
            for (edge in edges[point].orEmpty()) {
                val next = costs + edge.costs
                if (next < (best[edge.to]?.first ?: Long.MAX_VALUE)) {
                    val steps = best.getValue(point).second
                    best[edge.to] = next to steps + Step(edge.path, point, edge.to, routeIndex = steps.size)
                    queue.add(edge.to to next)
                }
            }
        }
        return null
    }

    private data class Edge(val path: String, val to: String, val costs: Long)

    private fun edges(avoid: Set<String>): Map<String, List<Edge>> = model().paths
        .filter { !it.locked && it.name !in avoid }
        .flatMap { path ->
            listOfNotNull(
                if (path.isNavigableForward) {
                    path.sourcePoint to Edge(
                        path.name,
                        path.destinationPoint,
                        path.length,
                    )
                } else {
                    null
                },
                if (path.isNavigableReverse) {
                    path.destinationPoint to Edge(
                        path.name,
                        path.sourcePoint,
                        path.length,
                    )
                } else {
                    null
                },
            )
        }
        .filter { (from, edge) -> from !in avoid && edge.to !in avoid }
        .groupBy({ it.first }, { it.second })
}
