package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonUnquotedLiteral
import org.ktcs.api.order.Route
import org.ktcs.kernel.web.LastEncoded
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

    private val last = LastEncoded<Route, EncodedRoute>(CAPACITY) {
        EncodedRoute(V1Json.json.encodeToString(RouteDto.serializer(), it.toDto()))
    }

    /** [route], the route of [driveOrder] (named by its transport order and its own name), as [RouteDto] JSON. */
    fun of(driveOrder: String, route: Route?): JsonElement = route?.let { last.of(driveOrder, it).json } ?: JsonNull

    /** The same as UTF-8, `null` for no route (see [of]). */
    fun utf8Of(driveOrder: String, route: Route?): ByteArray? = route?.let { last.of(driveOrder, it).utf8 }

    /** One route's JSON, as a literal to put in a tree and as UTF-8 (made when first asked for). */
    private class EncodedRoute(text: String) {
        @OptIn(ExperimentalSerializationApi::class)
        val json: JsonElement = JsonUnquotedLiteral(text)

        val utf8: ByteArray by lazy { text.toByteArray(Charsets.UTF_8) }
    }
}
