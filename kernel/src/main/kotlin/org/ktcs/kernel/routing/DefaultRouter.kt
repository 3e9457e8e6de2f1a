package org.ktcs.kernel.routing

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.routing.Router

/**
 * The router openTCS ships as its default, on JGraphT: points are vertices, drivable path directions are edges
 * weighted with the summed [RouterConfiguration.edgeEvaluators].
 *
 * Graphs are built lazily, one per combination of what the configured cost functions read from a vehicle (see
 * [GraphKey]), and kept until the next [updateTopology]; resources to avoid mask a cached graph instead of rebuilding
 * it. Costs must not be negative unless the algorithm is [RoutingAlgorithm.BELLMAN_FORD], and routes beyond the
 * cheapest one (Yen's algorithm) need non-negative costs too.
 *
 * Confined to the kernel context, like every kernel component.
 */
class DefaultRouter(private val configuration: RouterConfiguration = RouterConfiguration()) : Router {
    private var graphs = RoutingGraphs(PlantModel(name = ""), configuration)

    override fun updateTopology(model: PlantModel) {
        graphs = RoutingGraphs(model, configuration)
    }

    override fun isGenerallyRoutable(order: TransportOrder): Boolean =
        isRoutableInPrinciple(graphs.generalReachability, legCandidates(order, includeLockedLocations = true))

    override fun routeOrder(vehicle: Vehicle, sourcePoint: String, order: TransportOrder): List<DriveOrder>? {
        val avoided = parseResourceNames(order.properties[RESOURCES_TO_AVOID_PROPERTY])
        val search = searchFor(vehicle, sourcePoint, avoided)
        val legs = legCandidates(order, includeLockedLocations = false)
        val routes = CheapestOrderRoute(search, stayWhenPossible = !configuration.routeToCurrentPosition)
            .compute(sourcePoint, legs) ?: return null
        return order.driveOrders.zip(routes) { driveOrder, route -> driveOrder.copy(route = route) }
    }

    override fun routes(
        vehicle: Vehicle,
        sourcePoint: String,
        destinationPoint: String,
        resourcesToAvoid: Set<String>,
        maxRoutes: Int,
    ): List<Route> {
        require(maxRoutes >= 1) { "maxRoutes must be at least 1, was $maxRoutes" }
        val count = minOf(maxRoutes, configuration.routeComputationLimit)
        return searchFor(vehicle, sourcePoint, resourcesToAvoid).cheapest(sourcePoint, destinationPoint, count)
    }

    override fun costsFrom(vehicle: Vehicle, sourcePoint: String): (String) -> Long? =
        searchFor(vehicle, sourcePoint, emptySet()).costsFrom(sourcePoint)

    private fun searchFor(vehicle: Vehicle, sourcePoint: String, avoided: Collection<String>): RouteSearch {
        val search = graphs.searchFor(configuration.graphKeyOf(vehicle))
        return search.avoiding(AvoidedResources.of(graphs.model, avoided, sourcePoint))
    }

    private fun legCandidates(order: TransportOrder, includeLockedLocations: Boolean): List<List<String>> =
        order.driveOrders.map { graphs.model.destinationPoints(it.destination, includeLockedLocations) }
}
