package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonUnquotedLiteral
import org.ktcs.api.order.Route
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.orders.RouteDto
import org.ktcs.kernel.web.v1.orders.toDto

/**
 * The routes of the drive orders changed last, as JSON, by identity. An order under way changes at every step its
 * vehicle drives, while its route stays the same object: encoded once, a route is then copied into each event as it
 * is, so an event costs in proportion to what changed rather than to the route's length. Safe to use from several
 * threads (every event stream shares it).
 */
internal object EncodedRoutes {
    private const val CAPACITY = 512

    private val last = object : LinkedHashMap<String, Pair<Route, JsonElement>>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<String, Pair<Route, JsonElement>>) =
            size > CAPACITY
    }

    /** [route], the route of [driveOrder] (named by its transport order and its own name), as [RouteDto] JSON. */
    fun of(driveOrder: String, route: Route?): JsonElement {
        if (route == null) return JsonNull
        synchronized(last) { last[driveOrder]?.takeIf { it.first === route }?.let { return it.second } }
        val encoded = encode(route)
        synchronized(last) { last[driveOrder] = route to encoded }
        return encoded
    }

    @OptIn(ExperimentalSerializationApi::class)
    private fun encode(route: Route): JsonElement =
        JsonUnquotedLiteral(V1Json.json.encodeToString(RouteDto.serializer(), route.toDto()))
}
