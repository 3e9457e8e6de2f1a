package org.ktcs.api.service

/** Asks the dispatcher to act. Every method may be called from any coroutine. */
public interface DispatcherService {
    /** Runs the dispatcher now (it also runs by itself whenever an order or a vehicle becomes ready). */
    public suspend fun dispatch()

    /**
     * Withdraws an order. Regular withdrawal lets the vehicle finish the movements it was already sent; [immediate]
     * stops it at once (its command queue is cleared). [disableVehicle] also takes the vehicle out of dispatching
     * (integration level TO_BE_RESPECTED), as openTCS's web API v1 does.
     */
    public suspend fun withdrawByTransportOrder(order: String, immediate: Boolean, disableVehicle: Boolean = false)

    /** Withdraws the order the vehicle is processing, if any; see [withdrawByTransportOrder]. */
    public suspend fun withdrawByVehicle(vehicle: String, immediate: Boolean, disableVehicle: Boolean = false)

    /** Assigns a DISPATCHABLE order to its intended vehicle now, if that vehicle is free for it. */
    public suspend fun assignNow(order: String)

    /**
     * Computes a new route for the rest of the vehicle's current drive order: regular from where the vehicle will be
     * after the commands it was already sent, [forced] from where it stands (also off its route; the commands sent are
     * dropped, so only for a vehicle that stands still). Throws an IllegalStateChangeException naming why when the
     * vehicle has no order, stands off its route (regular) or no route leads on.
     */
    public suspend fun reroute(vehicle: String, forced: Boolean = false)
}
