package org.ktcs.kernel.routing

import org.ktcs.api.model.PlantModel

/**
 * The routing graphs of one plant model: one per [GraphKey], each built on first use and kept, with its search, for as
 * long as the model is current. Confined to the kernel context, like the router.
 */
internal class RoutingGraphs(val model: PlantModel, private val configuration: RouterConfiguration) {
    private val searches = HashMap<GraphKey, RouteSearch>()
    private val generalByKey = HashMap<GraphKey, RoutingGraph>()
    private val reachabilityByKey = HashMap<GraphKey, Reachability>()

    /** Every drivable path direction, locked or not, at cost 1: what general routability asks about. */
    val general: RoutingGraph by lazy { buildRoutingGraph(model, includeLocked = true) { _, _ -> 1 } }

    /** Reachability in [general], from its strongly connected components: built once per model, on first use. */
    val generalReachability: Reachability by lazy { Reachability(general) }

    /**
     * Reachability on the path directions vehicles of [key] may drive, locked or not, around [avoided]: kept per key
     * while nothing is avoided, computed for the order otherwise.
     */
    fun reachabilityFor(key: GraphKey, avoided: AvoidedResources): Reachability =
        if (avoided.isEmpty()) {
            reachabilityByKey.getOrPut(key) { Reachability(generalFor(key)) }
        } else {
            Reachability(generalFor(key).without(avoided))
        }

    private fun generalFor(key: GraphKey): RoutingGraph = generalByKey.getOrPut(key) {
        val costs = EdgeCosts(model, configuration, key)
        buildRoutingGraph(model, includeLocked = true, costs::of)
    }

    /** The search over the graph for vehicles of [key], without resources to avoid. */
    fun searchFor(key: GraphKey): RouteSearch = searches.getOrPut(key) {
        val costs = EdgeCosts(model, configuration, key)
        RouteSearch(buildRoutingGraph(model, includeLocked = false, costs::of), configuration.algorithm)
    }
}
