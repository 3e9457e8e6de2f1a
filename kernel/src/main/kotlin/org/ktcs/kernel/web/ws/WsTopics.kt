package org.ktcs.kernel.web.ws

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.encodeToJsonElement
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.LocationEvent
import org.ktcs.api.event.ObjectEvent
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.PathEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.UserNotification
import org.ktcs.api.event.UserNotificationEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.toSseDto
import org.ktcs.kernel.web.v1.plantmodel.toDto
import org.ktcs.kernel.web.v1.toWire

/** How each topic's objects and changes look on the wire (the SSE shapes of web API v1, plus paths/locations). */
internal object WsTopics {
    private val json = V1Json.json

    suspend fun snapshot(topic: WsTopic, services: KernelServices): List<JsonElement> = when (topic) {
        WsTopic.VEHICLES -> services.vehicles.vehicles().map { json.encodeToJsonElement(it.toSseDto()) }

        WsTopic.TRANSPORT_ORDERS -> services.transportOrders.transportOrders().map {
            json.encodeToJsonElement(it.toSseDto())
        }

        WsTopic.ORDER_SEQUENCES -> services.transportOrders.orderSequences().map {
            json.encodeToJsonElement(it.toSseDto())
        }

        WsTopic.PLANT_MODEL -> listOf(json.encodeToJsonElement(services.plantModel.plantModel().toDto()))

        WsTopic.NOTIFICATIONS -> services.notifications.notifications().map { json.encodeToJsonElement(it.toDto()) }
    }

    /** The topic and the previous/current state of [event] on the wire, or `null` for events no topic carries. */
    fun change(event: KernelEvent): Change? = when (event) {
        is VehicleEvent -> Change.of(WsTopic.VEHICLES, event) { json.encodeToJsonElement(it.toSseDto()) }

        is TransportOrderEvent -> Change.of(WsTopic.TRANSPORT_ORDERS, event) { json.encodeToJsonElement(it.toSseDto()) }

        is OrderSequenceEvent -> Change.of(WsTopic.ORDER_SEQUENCES, event) { json.encodeToJsonElement(it.toSseDto()) }

        is PathEvent -> Change.of(WsTopic.PLANT_MODEL, event) { json.encodeToJsonElement(it.toDto()) }

        is LocationEvent -> Change.of(WsTopic.PLANT_MODEL, event) { json.encodeToJsonElement(it.toDto()) }

        is UserNotificationEvent -> Change(
            WsTopic.NOTIFICATIONS,
            null,
            json.encodeToJsonElement(event.notification.toDto()),
        )

        else -> null
    }
}

/** One change of a topic's object, as it goes on the wire. */
internal data class Change(val topic: WsTopic, val previous: JsonElement?, val current: JsonElement?) {
    companion object {
        fun <T : Any> of(topic: WsTopic, event: ObjectEvent<T>, encode: (T) -> JsonElement) =
            Change(topic, event.previous?.let(encode), event.current?.let(encode))
    }
}

@kotlinx.serialization.Serializable
internal data class NotificationDto(val source: String?, val text: String, val level: String, val timestamp: String)

internal fun UserNotification.toDto() = NotificationDto(source, text, level.name, timestamp.toWire())
