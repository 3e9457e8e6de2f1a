package org.ktcs.kernel.web.ws

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.json.JsonUnquotedLiteral
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.LastEncoded
import org.ktcs.kernel.web.v1.ObjectHistoryDto
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.EncodedRoutes
import org.ktcs.kernel.web.v1.events.SseTransportOrderDto
import org.ktcs.kernel.web.v1.events.toSseDto
import org.ktcs.kernel.web.v1.toDto

/**
 * A transport order's event state as UTF-8 JSON, its routes spliced in as bytes: the order is encoded with a mark
 * where each route goes, and the routes' bytes, encoded once per route ([EncodedRoutes]), are copied in. The routes
 * are most of an order's JSON and stay the same while the order advances step by step, so they are neither encoded
 * nor copied character by character again at every step.
 */
internal object EncodedOrders {
    private const val HISTORY_CAPACITY = 512

    // A raw control character cannot occur in JSON that kotlinx writes (it escapes them in strings): a safe mark.
    private const val MARK: Byte = 1

    @OptIn(ExperimentalSerializationApi::class)
    private val markLiteral = JsonUnquotedLiteral("\u0001")

    // The history of the orders that changed last, by identity: an order advancing a step keeps its history, which a
    // client that has it is not sent (`omitUnchanged`), so it is encoded only when it changed and somebody takes it.
    private val histories = LastEncoded<List<HistoryEntry>, ByteArray>(HISTORY_CAPACITY) {
        utf8(V1Json.json.encodeToString(ObjectHistoryDto.serializer(), it.toDto()))
    }

    fun utf8(order: TransportOrder): ByteArray = marked(order).full

    /**
     * [order] encoded with a mark where each route goes and its history left empty, with the routes and the history:
     * put together only when needed.
     */
    fun marked(order: TransportOrder): Marked {
        val routes = order.driveOrders.map { EncodedRoutes.utf8Of("${order.name}/${it.name}", it.route) }
        val dto = order.toSseDto(withHistory = false)
        val marked = dto.copy(
            driveOrders = dto.driveOrders.mapIndexed { index, driveOrder ->
                if (routes[index] == null) driveOrder else driveOrder.copy(route = markLiteral)
            },
        )
        return Marked(
            utf8(V1Json.json.encodeToString(SseTransportOrderDto.serializer(), marked)),
            routes.filterNotNull(),
            lazy { histories.of(order.name, order.history) },
        )
    }

    /** An order's JSON with its routes' marks and an empty history ([text]), the routes' bytes and the history's. */
    class Marked(
        private val text: ByteArray,
        private val routes: List<ByteArray>,
        historyBytes: Lazy<ByteArray>,
    ) : MarkedJson {
        private val history = mapOf("history" to historyBytes::value)

        override val full: ByteArray by lazy { splice(rewriteFields(text, emptyList(), history), routes) }

        /**
         * The order without its top-level [fields]: cut from the marked text, which is short, so that a client that
         * has the routes does not cost a scan over them.
         */
        override fun without(fields: List<String>): ByteArray =
            splice(rewriteFields(text, fields, history), if ("driveOrders" in fields) emptyList() else routes)
    }

    /** [text] with each [MARK] replaced by the next of [routes]. */
    private fun splice(text: ByteArray, routes: List<ByteArray>): ByteArray {
        if (routes.isEmpty()) return text
        val out = ByteArray(text.size - routes.size + routes.sumOf { it.size })
        var from = 0
        var to = 0
        for (route in routes) {
            val mark = indexOf(text, from)
            text.copyInto(out, to, from, mark)
            to += mark - from
            route.copyInto(out, to)
            to += route.size
            from = mark + 1
        }
        text.copyInto(out, to, from, text.size)
        return out
    }

    private fun indexOf(text: ByteArray, from: Int): Int {
        for (i in from until text.size) if (text[i] == MARK) return i
        error("a route's mark is missing from the order's JSON")
    }
}
