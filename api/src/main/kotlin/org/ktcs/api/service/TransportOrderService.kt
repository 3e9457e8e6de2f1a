package org.ktcs.api.service

import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation

/**
 * Creates and reads transport orders and order sequences. Every method may be called from any coroutine; the work
 * happens in the kernel context. Refusals are [org.ktcs.api.error.KernelException]s naming the problem.
 */
public interface TransportOrderService {
    /**
     * Creates a transport order, checked as openTCS does: names unique, destinations exist, a location's operation
     * allowed by its type and by a link, a point's operation MOVE or PARK, dependencies and sequence known.
     */
    public suspend fun createTransportOrder(creation: TransportOrderCreation): TransportOrder

    /** The order named [name], or `null`. */
    public suspend fun transportOrder(name: String): TransportOrder?

    /** All orders, or those intended for [intendedVehicle]. */
    public suspend fun transportOrders(intendedVehicle: String? = null): List<TransportOrder>

    /** Changes the vehicle an order is intended for (`null`: any); only before the order is assigned. */
    public suspend fun setIntendedVehicle(order: String, vehicle: String?)

    /** Creates an order sequence. */
    public suspend fun createOrderSequence(creation: OrderSequenceCreation): OrderSequence

    /** The sequence named [name], or `null`. */
    public suspend fun orderSequence(name: String): OrderSequence?

    /** All sequences, or those intended for [intendedVehicle]. */
    public suspend fun orderSequences(intendedVehicle: String? = null): List<OrderSequence>

    /** Marks a sequence complete: no more orders will be added. Irreversible. */
    public suspend fun markOrderSequenceComplete(name: String)
}
