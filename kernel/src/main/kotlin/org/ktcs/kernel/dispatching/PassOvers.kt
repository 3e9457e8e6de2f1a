package org.ktcs.kernel.dispatching

import org.ktcs.api.order.TransportOrder

/**
 * How often each waiting order was passed over: a vehicle that had it among the orders it chose from took a less
 * urgent one (see [DispatcherConfiguration.orderCandidateWindow]). An order passed over [limit] times is due: the
 * next vehicle that can take it takes it before any other. Kept between runs; an order is forgotten when it is
 * assigned, and by [retainOnly] once it no longer waits.
 */
internal class PassOvers(private val limit: Int) {
    private val counts = HashMap<String, Int>()

    fun isDue(order: TransportOrder): Boolean = limit > 0 && (counts[order.name] ?: 0) >= limit

    /** [chosen] was taken from [window], whose orders are ranked most urgent first: the ones before it were passed. */
    fun chose(chosen: TransportOrder, window: List<TransportOrder>) {
        for (order in window) {
            if (order.name == chosen.name) break
            counts.merge(order.name, 1, Int::plus)
        }
        counts.remove(chosen.name)
    }

    fun retainOnly(waiting: Set<String>) {
        counts.keys.retainAll(waiting)
    }
}
