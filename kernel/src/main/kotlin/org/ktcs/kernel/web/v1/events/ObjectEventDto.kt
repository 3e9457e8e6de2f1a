package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.Serializable
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent

/**
 * The payload of an SSE event (`/events/vehicles`, `/events/transportOrders`, `/events/orderSequences`): the object
 * after and before the change, `null` where it did not exist.
 */
@Serializable
data class ObjectEventDto<T>(val currentObjectState: T?, val previousObjectState: T?)

fun TransportOrderEvent.toDto(): ObjectEventDto<SseTransportOrderDto> =
    ObjectEventDto(current?.toSseDto(), previous?.toSseDto())

fun VehicleEvent.toDto(): ObjectEventDto<SseVehicleDto> = ObjectEventDto(current?.toSseDto(), previous?.toSseDto())

fun OrderSequenceEvent.toDto(): ObjectEventDto<SseOrderSequenceDto> =
    ObjectEventDto(current?.toSseDto(), previous?.toSseDto())

/** SSE event names, as openTCS's v1 `/sse` endpoint uses them. */
object SseEventNames {
    const val VEHICLES = "/events/vehicles"
    const val TRANSPORT_ORDERS = "/events/transportOrders"
    const val ORDER_SEQUENCES = "/events/orderSequences"

    /** kTCS's own: events vehicle drivers publish. */
    const val DRIVER_EVENTS = "/events/driverEvents"
}
