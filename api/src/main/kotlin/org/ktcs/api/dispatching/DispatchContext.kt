package org.ktcs.api.dispatching

import org.ktcs.api.kernel.Explained
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.routing.Router

/**
 * What a [Dispatcher] can see and do. Valid in the kernel context only; reads reflect the state at the moment of
 * the call.
 */
public interface DispatchContext {
    /** The kernel's clock. */
    public val clock: KernelClock

    /** The router, for costs and routes. */
    public val router: Router

    /** The plant with its current path and location locks; its vehicles are as loaded (use [vehicles]). */
    public fun plantModel(): PlantModel

    /** Every vehicle, with its runtime state. */
    public fun vehicles(): Collection<Vehicle>

    /** The orders in state DISPATCHABLE, oldest first. */
    public fun dispatchableOrders(): Collection<TransportOrder>

    /** The order named [name], or `null`. */
    public fun transportOrder(name: String): TransportOrder?

    /** The order sequence named [name], or `null`. */
    public fun orderSequence(name: String): OrderSequence?

    /** Whether the vehicle's driver accepts [order] (a "no" says why). */
    public fun driverAccepts(vehicle: String, order: TransportOrder): Explained

    /**
     * Gives [order] (DISPATCHABLE) to [vehicle] with the routed [driveOrders] (from [Router.routeOrder]). If the
     * vehicle is processing a dispensable order, that order is withdrawn first.
     */
    public fun assign(order: String, vehicle: String, driveOrders: List<DriveOrder>)

    /** Creates an order, e.g. to park or recharge a vehicle; it becomes DISPATCHABLE in the same run. */
    public fun createTransportOrder(creation: TransportOrderCreation): TransportOrder

    /** Notes in the order's history why it was not assigned yet (shown to operators; repeated reasons are merged). */
    public fun orderWaiting(order: String, reason: String)

    /**
     * Notes why [vehicle], idle, took no order in this run (`null`: it took one, or no order waits), as
     * [org.ktcs.api.model.Vehicle.waitingReason]. Called for every vehicle in every run; the kernel keeps only changes.
     */
    public fun vehicleWaiting(vehicle: String, reason: String?)
}
