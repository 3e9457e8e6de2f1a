package org.ktcs.kernel.routing

import org.ktcs.api.model.PlantModel

/**
 * The routing graphs of one plant model: one per [GraphKey], each built on first use and kept, with its search, for as
 * long as the model is current. Confined to the kernel context, like the router.
 */
internal class RoutingGraphs(val model: PlantModel, private val configuration: RouterConfiguration) {
    private val searches = HashMap<GraphKey, RouteSearch>()

    /** Every drivable path direction, locked or not, at cost 1: what general routability asks about. */
    val general: RoutingGraph by lazy { buildRoutingGraph(model, includeLocked = true) { _, _ -> 1 } }

    /** Reachability in [general], from its strongly connected components: built once per model, on first use. */
    val generalReachability: Reachability by lazy { Reachability(general) }

    /** The search over the graph for vehicles of [key], without resources to avoid. */
    fun searchFor(key: GraphKey): RouteSearch = searches.getOrPut(key) {
        val costs = EdgeCosts(model, configuration, key)
        RouteSearch(buildRoutingGraph(model, includeLocked = false, costs::of), configuration.algorithm)
    }
}
