package org.ktcs.adapters.vda5050.protocol

/**
 * Encodes one vehicle's order messages to exactly the JSON [Vda5050Json] gives, but each node and edge once per
 * order: every order update repeats the base from the stitching node and the whole horizon (VDA 5050 asks for it),
 * so almost all of an update's nodes and edges were in the one before, and their coordinates, lengths and speeds
 * need not be formatted again. Not thread-safe: one per vehicle, used by one thread at a time.
 */
internal class OrderEncoder {
    private var orderId: String? = null
    private val nodes = HashMap<Node, String>()
    private val edges = HashMap<Edge, String>()

    /** [order] as JSON. */
    fun encode(order: Order): String {
        if (order.orderId != orderId) {
            orderId = order.orderId
            nodes.clear()
            edges.clear()
        }
        val head = Vda5050Json.encodeToString(Order.serializer(), order.copy(nodes = emptyList(), edges = emptyList()))
        // Anything after the two arrays (a zoneSetId) would follow them: such an order is encoded as a whole.
        if (!head.endsWith(EMPTY_ARRAYS)) return Vda5050Json.encodeToString(Order.serializer(), order)
        return buildString(head.length + (order.nodes.size + order.edges.size) * ELEMENT_SIZE_GUESS) {
            append(head, 0, head.length - EMPTY_ARRAYS.length)
            append("\"nodes\":[")
            order.nodes.forEachIndexed { i, node ->
                if (i > 0) append(',')
                append(nodes.getOrPut(node) { Vda5050Json.encodeToString(Node.serializer(), node) })
            }
            append("],\"edges\":[")
            order.edges.forEachIndexed { i, edge ->
                if (i > 0) append(',')
                append(edges.getOrPut(edge) { Vda5050Json.encodeToString(Edge.serializer(), edge) })
            }
            append("]}")
        }
    }

    private companion object {
        const val EMPTY_ARRAYS = "\"nodes\":[],\"edges\":[]}"
        const val ELEMENT_SIZE_GUESS = 160
    }
}
