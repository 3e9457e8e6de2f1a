package org.ktcs.kernel.web.v1.events

import io.ktor.http.CacheControl
import io.ktor.http.ContentType
import io.ktor.server.response.cacheControl
import io.ktor.server.response.respond
import io.ktor.server.response.respondBytesWriter
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.utils.io.writeStringUtf8
import kotlinx.serialization.json.Json
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.booleanQuery
import org.ktcs.kernel.web.v1.drivers.DriverEventDto
import org.ktcs.kernel.web.v1.drivers.toDto
import org.ktcs.kernel.web.v1.toWire
import java.time.Instant

/**
 * `GET /events` (long polling over [buffer], openTCS's parameters and limits) and `GET /sse` (Server-Sent Events
 * named as openTCS names them, for the kinds the client asks for). A client too slow for the event stream is cut
 * off and may reconnect.
 */
fun Route.eventRoutes(services: KernelServices, buffer: StatusEventBuffer) {
    get("/events") {
        val min = call.longQuery("minSequenceNo", 0)
        val max = call.longQuery("maxSequenceNo", Long.MAX_VALUE)
        val timeout = call.longQuery("timeout", DEFAULT_TIMEOUT_MILLIS)
        if (min < 0 || max < min) {
            throw InvalidRequestException("need 0 <= minSequenceNo <= maxSequenceNo, got $min and $max")
        }
        if (timeout !in 0..MAX_TIMEOUT_MILLIS) {
            throw InvalidRequestException("timeout must be between 0 and $MAX_TIMEOUT_MILLIS ms, was $timeout")
        }
        call.respond(GetEventsResponse(Instant.now().toWire(), buffer.await(min, max, timeout)))
    }
    get("/sse") {
        val wanted = SSE_KINDS.filter { call.booleanQuery(it) }.toSet()
        call.response.cacheControl(CacheControl.NoCache(null))
        // Subscribed before the client hears anything: a change it makes once the stream answered is on the stream.
        val (_, events) = services.eventsAfter {}
        call.respondBytesWriter(ContentType.Text.EventStream) {
            writeStringUtf8(": kTCS event stream\n\n")
            flush()
            events.collect { event ->
                sseFrame(event, wanted)?.let {
                    writeStringUtf8(it)
                    flush()
                }
            }
        }
    }
}

private fun io.ktor.server.application.ApplicationCall.longQuery(name: String, default: Long): Long {
    val raw = request.queryParameters[name] ?: return default
    return raw.toLongOrNull()
        ?: throw InvalidRequestException("query parameter $name must be a whole number, was '$raw'")
}

private fun sseFrame(event: KernelEvent, wanted: Set<String>): String? {
    val json: Json = V1Json.json
    val (name, data) = when (event) {
        is VehicleEvent ->
            SseEventNames.VEHICLES to
                json.encodeToString(ObjectEventDto.serializer(SseVehicleDto.serializer()), event.toDto())

        is TransportOrderEvent ->
            SseEventNames.TRANSPORT_ORDERS to
                json.encodeToString(ObjectEventDto.serializer(SseTransportOrderDto.serializer()), event.toDto())

        is OrderSequenceEvent ->
            SseEventNames.ORDER_SEQUENCES to
                json.encodeToString(ObjectEventDto.serializer(SseOrderSequenceDto.serializer()), event.toDto())

        is DriverEvent -> SseEventNames.DRIVER_EVENTS to json.encodeToString(DriverEventDto.serializer(), event.toDto())

        else -> return null
    }
    return if (name in wanted) "event: $name\ndata: $data\n\n" else null
}

private val SSE_KINDS = listOf(
    SseEventNames.VEHICLES,
    SseEventNames.TRANSPORT_ORDERS,
    SseEventNames.ORDER_SEQUENCES,
    SseEventNames.DRIVER_EVENTS,
)
private const val DEFAULT_TIMEOUT_MILLIS = 1_000L
private const val MAX_TIMEOUT_MILLIS = 10_000L
