package org.ktcs.api.routing

import org.ktcs.api.kernel.KernelComponent
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder

/**
 * Computes routes through the roadmap. The router ignores other vehicles: avoiding them is the scheduler's job.
 *
 * Points are the vertices of the routing graph and every drivable direction of a path is an edge (a direction with
 * maximum velocity 0 is not drivable); locked paths are left out. Vehicles with the same routing group (vehicle
 * property `tcs:routingGroup`) share one graph.
 */
public interface Router : KernelComponent {
    /**
     * Rebuilds the routing graphs from [model]; called when the kernel starts, when the model is replaced and when
     * paths are locked or unlocked.
     */
    public fun updateTopology(model: PlantModel)

    /**
     * Whether [order] could be carried out by some vehicle in principle: every destination is reachable from the
     * previous one, ignoring path locks and cost functions. An order that is not is marked UNROUTABLE.
     */
    public fun isGenerallyRoutable(order: TransportOrder): Boolean

    /**
     * The drive orders of [order] with a route each, for [vehicle] starting at the point [sourcePoint], choosing for
     * every location the linked point that gives the cheapest route overall; `null` if there is no such route.
     * The property `tcs:resourcesToAvoid` of the order (comma-separated names) excludes points, paths and locations.
     */
    public fun routeOrder(vehicle: Vehicle, sourcePoint: String, order: TransportOrder): List<DriveOrder>?

    /**
     * Up to [maxRoutes] cheapest routes for [vehicle] from [sourcePoint] to [destinationPoint], cheapest first,
     * avoiding the points, paths and locations named in [resourcesToAvoid]; empty if there is none. A route from a
     * point to itself has one step without a path.
     */
    public fun routes(
        vehicle: Vehicle,
        sourcePoint: String,
        destinationPoint: String,
        resourcesToAvoid: Set<String> = emptySet(),
        maxRoutes: Int = 1,
    ): List<Route>

    /**
     * The costs of the cheapest routes from [sourcePoint] for [vehicle], as a function of the destination point
     * (`null`: unreachable). A router should answer all destinations from one search, e.g. to find the closest of
     * many parking positions; this default asks [routes] once per destination.
     */
    public fun costsFrom(vehicle: Vehicle, sourcePoint: String): (String) -> Long? =
        { destination -> routes(vehicle, sourcePoint, destination).firstOrNull()?.costs }

    /**
     * The costs of the cheapest routes to [destinationPoint] for [vehicle], as a function of the source point (`null`:
     * no route). A router should answer all sources from one search backwards, e.g. to rank many vehicles by their
     * distance to an order's first destination; this default asks [costsFrom] once per source.
     */
    public fun costsTo(vehicle: Vehicle, destinationPoint: String): (String) -> Long? =
        { source -> costsFrom(vehicle, source)(destinationPoint) }
}
