package org.ktcs.api.service

import kotlinx.coroutines.flow.Flow
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.order.Route

/**
 * The only way into the kernel, for the web API, the XML channels, drivers' clients and extensions alike.
 */
public interface KernelServices {
    /** Transport orders and order sequences. */
    public val transportOrders: TransportOrderService

    /** Dispatching, withdrawals, rerouting. */
    public val dispatcher: DispatcherService

    /** Vehicles and their drivers. */
    public val vehicles: VehicleService

    /** The plant model, locks, topology. */
    public val plantModel: PlantModelService

    /** User notifications. */
    public val notifications: NotificationService

    /** Route queries. */
    public val router: RouterService

    /**
     * Every kernel event from now on, in kernel order. A collector that falls far behind fails with an exception
     * saying it missed events; it should collect again and start from a fresh snapshot.
     */
    public fun events(): Flow<KernelEvent>

    /**
     * Takes [snapshot] and subscribes to the events after it in one step, in the kernel context: the flow starts
     * with the first change after the snapshot, so a client that applies the snapshot and then the events neither
     * misses a change nor sees one twice. [snapshot] may call the other services; it must not block.
     */
    public suspend fun <T> eventsAfter(snapshot: suspend () -> T): Pair<T, Flow<KernelEvent>>
}

/** Route queries, e.g. "how would this vehicle get there?". */
public interface RouterService {
    /**
     * Up to [maxRoutes] routes for [vehicle] from [sourcePoint] (default: where it is) to each of
     * [destinationPoints], avoiding [resourcesToAvoid]; a destination without a route maps to an empty list.
     */
    public suspend fun computeRoutes(
        vehicle: String,
        sourcePoint: String?,
        destinationPoints: List<String>,
        resourcesToAvoid: Set<String> = emptySet(),
        maxRoutes: Int = 1,
    ): Map<String, List<Route>>
}
