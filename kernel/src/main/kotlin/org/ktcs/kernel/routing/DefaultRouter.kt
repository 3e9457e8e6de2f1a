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

    /**
     * Whether some vehicle that may take [order] (its intended vehicle, else any) could route it in principle, on the
     * paths it may drive and around the order's `tcs:resourcesToAvoid`; locks are ignored, as they are temporary.
     * Answered from the plant's strongly connected components first; only orders that pass that are checked per kind
     * of vehicle.
     */
    override fun isGenerallyRoutable(order: TransportOrder): Boolean {
        val legs = legCandidates(order, includeLockedLocations = true)
        if (!isRoutableInPrinciple(graphs.generalReachability, legs)) return false
        val avoided = AvoidedResources.of(
            graphs.model,
            parseResourceNames(order.properties[RESOURCES_TO_AVOID_PROPERTY]),
            "",
        )
        val usableLegs = legs.map { points -> points.filter { it !in avoided.points } }
        val vehicles = order.intendedVehicle?.let { listOfNotNull(graphs.model.vehicle(it)) } ?: graphs.model.vehicles
        if (vehicles.isEmpty()) {
            return avoided.isEmpty() ||
                isRoutableInPrinciple(Reachability(graphs.general.without(avoided)), usableLegs)
        }
        return vehicles.map(configuration::graphKeyOf).distinct().any { key ->
            isRoutableInPrinciple(graphs.reachabilityFor(key, avoided), usableLegs)
        }
    }

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

    override fun costsTo(vehicle: Vehicle, destinationPoint: String): (String) -> Long? =
        graphs.searchFor(configuration.graphKeyOf(vehicle)).costsTo(destinationPoint)

    private fun searchFor(vehicle: Vehicle, sourcePoint: String, avoided: Collection<String>): RouteSearch {
        val search = graphs.searchFor(configuration.graphKeyOf(vehicle))
        return search.avoiding(AvoidedResources.of(graphs.model, avoided, sourcePoint))
    }

    private fun legCandidates(order: TransportOrder, includeLockedLocations: Boolean): List<List<String>> =
        order.driveOrders.map { graphs.model.destinationPoints(it.destination, includeLockedLocations) }
}
