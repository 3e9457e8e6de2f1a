package org.ktcs.kernel.web.ws

import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.LastEncoded
import org.ktcs.kernel.web.v1.ObjectHistoryDto
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.toDto

/**
 * Transport orders' event states as UTF-8 JSON, written by [OrderJsonWriter], their routes
 * ([org.ktcs.kernel.web.v1.events.EncodedRoutes]) and histories copied in as bytes. The routes are most of an order's
 * JSON and stay the same while the order advances step by step, so they are neither encoded nor copied character by
 * character again at every step. The values of the fields that seldom change ([SteadyOrderFields]) and the histories
 * are kept for the [CAPACITY] most recently changed orders. Safe to use from several threads.
 */
internal object EncodedOrders {
    private const val CAPACITY = 512

    // An order advancing a step keeps its history, which a client that has it is not sent (`omitUnchanged`), so it is
    // encoded only when it changed and somebody takes it.
    private val histories = LastEncoded<List<HistoryEntry>, ByteArray>(CAPACITY) {
        utf8(V1Json.json.encodeToString(ObjectHistoryDto.serializer(), it.toDto()))
    }
    private val steady = LastEncoded<TransportOrder, SteadyOrderFields>(CAPACITY, ::steadyFieldsOf)

    fun utf8(order: TransportOrder): ByteArray = marked(order).full

    /** [order]'s JSON, whole or without some fields, each part of it made only when written. */
    fun marked(order: TransportOrder): MarkedJson = OrderJsonWriter(
        order,
        steady.of(order.name, order),
        lazy { histories.of(order.name, order.history) },
    )

    private fun steadyFieldsOf(order: TransportOrder): SteadyOrderFields =
        SteadyOrderFields.of(order, steady.lastOf(order.name))
}
