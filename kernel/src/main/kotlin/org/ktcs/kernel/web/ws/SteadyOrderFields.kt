package org.ktcs.kernel.web.ws

import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.events.EncodedRoutes
import java.time.Instant

/**
 * The JSON values of the fields of a transport order that seldom change, each with the object it was made of. An
 * order under way is a new [TransportOrder] at every step its vehicle drives that shares these objects with the one
 * before (`copy` keeps them), so they are encoded again only when one of them is another object ([of]).
 */
internal class SteadyOrderFields private constructor(
    val name: Encoded<String>,
    val properties: Encoded<Map<String, String>>,
    val type: Encoded<String>,
    val dependencies: Encoded<Set<String>>,
    val driveOrders: DriveOrdersJson,
    val creationTime: Encoded<Instant>,
    val deadline: Encoded<Instant>,
    /** The finished time, or v1's far-future instant for an order that is not finished. */
    val finishedTime: Encoded<Instant>,
) {
    private fun isOf(order: TransportOrder): Boolean = name.source === order.name &&
        properties.source === order.properties &&
        type.source === order.type &&
        dependencies.source === order.dependencies &&
        driveOrders.isOf(order) &&
        creationTime.source === order.creationTime &&
        deadline.source === order.deadline &&
        finishedTime.source === finishedTimeOf(order)

    companion object {
        /** [order]'s values, reusing those of [last] (the same order's, encoded before) that are of its objects. */
        fun of(order: TransportOrder, last: SteadyOrderFields?): SteadyOrderFields {
            if (last != null && last.isOf(order)) return last
            return SteadyOrderFields(
                last?.name.reusedFor(order.name, ::jsonString),
                last?.properties.reusedFor(order.properties, ::properties),
                last?.type.reusedFor(order.type, ::jsonString),
                last?.dependencies.reusedFor(order.dependencies, ::strings),
                last?.driveOrders?.takeIf { it.isOf(order) } ?: DriveOrdersJson(order.driveOrders, order.name),
                last?.creationTime.reusedFor(order.creationTime, ::timestamp),
                last?.deadline.reusedFor(order.deadline, ::timestamp),
                last?.finishedTime.reusedFor(finishedTimeOf(order), ::timestamp),
            )
        }

        // What `orMaxInstant` writes for an unfinished order; `Instant.MAX` is one object, so it is kept as well.
        private fun finishedTimeOf(order: TransportOrder) = order.finishedTime ?: Instant.MAX
    }
}

/**
 * The drive orders of the order named [orderName] as JSON but for their routes, which [EncodedRoutes] keeps: for each,
 * what goes before its route and what goes after it. Made when first written (a client that has them is not sent
 * them), and kept while the order holds the same list: its drive orders change a few times while it advances many
 * steps.
 */
internal class DriveOrdersJson(private val driveOrders: List<DriveOrder>, private val orderName: String) {
    val parts: Array<DriveOrderJson> by lazy { Array(driveOrders.size) { DriveOrderJson(orderName, driveOrders[it]) } }

    fun isOf(order: TransportOrder) = driveOrders === order.driveOrders && orderName === order.name
}

/** One drive order's JSON: [head], its route ([routeJson]) and [tail]. */
internal class DriveOrderJson(orderName: String, driveOrder: DriveOrder) {
    private val route = driveOrder.route

    // How EncodedRoutes knows the route, made once rather than at each look-up.
    private val routeKey = "$orderName/${driveOrder.name}"

    /** `{"name":…,"destination":{…},"transportOrder":…,"route":` */
    val head: ByteArray = json {
        raw(NAME)
        string(driveOrder.name)
        raw(DESTINATION)
        string(driveOrder.destination.target)
        raw(OPERATION)
        string(driveOrder.destination.operation)
        raw(PROPERTIES)
        stringMap(driveOrder.destination.properties)
        raw(TRANSPORT_ORDER)
        string(orderName)
        raw(ROUTE)
    }

    /** `,"state":"…"}` */
    val tail: ByteArray = TAILS[driveOrder.state.ordinal]

    /** The route's JSON, kept by [EncodedRoutes], or `null`. */
    fun routeJson(): ByteArray = EncodedRoutes.utf8Of(routeKey, route) ?: Utf8JsonOut.NULL

    private companion object {
        val NAME = utf8("""{"name":""")
        val DESTINATION = utf8(""","destination":{"destination":""")
        val OPERATION = utf8(""","operation":""")
        val PROPERTIES = utf8(""","properties":""")
        val TRANSPORT_ORDER = utf8("""},"transportOrder":""")
        val ROUTE = utf8(""","route":""")
        val TAILS = DriveOrderState.entries.map { utf8(""","state":"${it.name}"}""") }
    }
}

private fun strings(strings: Set<String>) = json { array(strings) { string(it) } }
