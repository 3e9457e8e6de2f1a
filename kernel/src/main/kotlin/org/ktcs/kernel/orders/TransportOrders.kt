package org.ktcs.kernel.orders

import org.ktcs.api.order.TransportOrder

/** The transport orders, read-only: what code outside the kernel's core may see of [TransportOrderPool]. */
interface TransportOrders {
    fun get(name: String): TransportOrder?

    fun require(name: String): TransportOrder

    fun all(): Collection<TransportOrder>

    fun contains(name: String): Boolean
}
