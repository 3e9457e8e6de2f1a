package org.ktcs.kernel.orders

import org.ktcs.api.order.OrderSequence

/** The order sequences, read-only: what code outside the kernel's core may see of [OrderSequencePool]. */
interface OrderSequences {
    fun get(name: String): OrderSequence?

    fun require(name: String): OrderSequence

    fun all(): Collection<OrderSequence>
}
