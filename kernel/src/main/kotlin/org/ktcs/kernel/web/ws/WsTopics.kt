package org.ktcs.kernel.web.ws

import kotlinx.serialization.encodeToString
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.encodeToJsonElement
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.LocationEvent
import org.ktcs.api.event.ObjectEvent
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.PathEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.UserNotification
import org.ktcs.api.event.UserNotificationEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.LastEncoded
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.drivers.toDto
import org.ktcs.kernel.web.v1.events.toSseDto
import org.ktcs.kernel.web.v1.plantmodel.toDto
import org.ktcs.kernel.web.v1.toWire
import java.util.concurrent.ConcurrentHashMap

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

        WsTopic.DRIVER_EVENTS -> services.vehicles.recentDriverEvents().map { json.encodeToJsonElement(it.toDto()) }
    }

    /** The topic that carries [event], or `null` if none does; tells whether [change] is needed at all. */
    fun topicOf(event: KernelEvent): WsTopic? = when (event) {
        is VehicleEvent -> WsTopic.VEHICLES
        is TransportOrderEvent -> WsTopic.TRANSPORT_ORDERS
        is OrderSequenceEvent -> WsTopic.ORDER_SEQUENCES
        is PathEvent, is LocationEvent -> WsTopic.PLANT_MODEL
        is UserNotificationEvent -> WsTopic.NOTIFICATIONS
        is DriverEvent -> WsTopic.DRIVER_EVENTS
        else -> null
    }

    /**
     * The topic and the previous/current state of [event] as UTF-8 JSON, or `null` for events no topic carries.
     * [encoded] keeps the last encoded states of vehicles and orders, which are the next events' previous states.
     */
    fun change(event: KernelEvent, encoded: EncodedObjects = EncodedObjects()): Change? = when (event) {
        is VehicleEvent -> Change.ofMarked(WsTopic.VEHICLES, event, encoded::vehicle)

        is TransportOrderEvent -> Change.ofMarked(WsTopic.TRANSPORT_ORDERS, event, encoded::order)

        is OrderSequenceEvent -> Change.of(WsTopic.ORDER_SEQUENCES, event) { utf8(json.encodeToString(it.toSseDto())) }

        is PathEvent -> Change.of(WsTopic.PLANT_MODEL, event) { utf8(json.encodeToString(it.toDto())) }

        is LocationEvent -> Change.of(WsTopic.PLANT_MODEL, event) { utf8(json.encodeToString(it.toDto())) }

        is UserNotificationEvent -> Change(
            WsTopic.NOTIFICATIONS,
            null,
            utf8(json.encodeToString(event.notification.toDto())),
        )

        is DriverEvent -> Change(WsTopic.DRIVER_EVENTS, null, utf8(json.encodeToString(event.toDto())))

        else -> null
    }
}

/** [text] as UTF-8 (`String.getBytes`, whose Latin-1 fast path Ktor's `Frame.Text(String)` does not take). */
internal fun utf8(text: String): ByteArray = text.toByteArray(Charsets.UTF_8)

/** The [LastEncoded] vehicles and transport orders that every WebSocket session of a server shares. */
internal class EncodedObjects(capacity: Int = DEFAULT_CAPACITY) {
    private val vehicleParts = EncodedVehicles(capacity)
    private val vehicles = LastEncoded<Vehicle, MarkedJson>(capacity, vehicleParts::marked)
    private val orders = LastEncoded<TransportOrder, MarkedJson>(capacity, EncodedOrders::marked)

    fun vehicle(vehicle: Vehicle): MarkedJson = vehicles.of(vehicle.name, vehicle)

    fun order(order: TransportOrder): MarkedJson = orders.of(order.name, order)

    private companion object {
        const val DEFAULT_CAPACITY = 512
    }
}

/** One change of a topic's object, its states as the UTF-8 JSON that goes on the wire. */
internal class Change(
    val topic: WsTopic,
    previousOf: () -> ByteArray?,
    currentOf: () -> ByteArray?,
    private val removed: Boolean,
    private val currentWithout: ((List<String>) -> ByteArray)? = null,
    private val currentOnly: ((List<String>) -> ByteArray)? = null,
) {
    constructor(topic: WsTopic, previous: ByteArray?, current: ByteArray?) :
        this(topic, { previous }, { current }, removed = current == null)

    // Encoded only if sent: a client that wants no previous states, or gets `current` without some fields, never
    // costs the whole state's bytes.
    val previous: ByteArray? by lazy(LazyThreadSafetyMode.NONE, previousOf)
    val current: ByteArray? by lazy(LazyThreadSafetyMode.NONE, currentOf)

    /**
     * The [WsEvent] message numbered [seq] as UTF-8 JSON, put together from the states' bytes, which sessions share:
     * copying them is all a session does per event, however many sessions follow it. Without [withPrevious], `previous`
     * is `null` unless the object was removed. The fields named in [unchanged] are left out of `current` (a cut of its
     * bytes, made by each session that asks for it) and listed in `unchanged`; the lists in [shortened] are left out
     * and listed in `shortened` with how many entries they lost from their front. With [changed] (the fields that
     * changed, for a client that subscribed with `onlyChanged`), `current` has the object's `name` and those fields
     * but for the [shortened] lists, and no `unchanged` list goes with it.
     */
    fun eventBytes(
        seq: Long,
        withPrevious: Boolean = true,
        unchanged: List<String> = emptyList(),
        shortened: Map<String, Int> = emptyMap(),
        changed: List<String>? = null,
    ): ByteArray {
        val head = utf8("""{"type":"event","topic":"${topic.wireName}","seq":$seq,"previous":""")
        // A client that asked for no previous states still needs a removed object's, to know which one went.
        val previous = if (withPrevious || removed) previous ?: NULL else NULL
        val only = changed?.takeUnless { removed || currentOnly == null }
        val left = if (removed || only != null) emptyList() else unchanged
        val cut = if (removed) emptyMap() else shortened
        val current = when {
            removed -> NULL
            only != null -> currentOnly!!(listOf(NAME) + only.filter { it !in cut })
            left.isEmpty() && cut.isEmpty() -> current!!
            else -> (left + cut.keys).let { currentWithout?.invoke(it) ?: withoutFields(current!!, it) }
        }
        val parts = arrayOf(head, previous, CURRENT, current, unchangedField(left), shortenedField(cut), TAIL)
        val out = ByteArray(parts.sumOf { it.size })
        var at = 0
        for (part in parts) {
            part.copyInto(out, at)
            at += part.size
        }
        return out
    }

    // The same few lists of unchanged fields come with most events: each list's bytes are made once. Only the
    // objects' own field names are listed, in their fixed order, so there are at most a few hundred such lists.
    private fun unchangedField(fields: List<String>): ByteArray = if (fields.isEmpty()) {
        EMPTY
    } else {
        UNCHANGED_LISTS.computeIfAbsent(fields) {
            utf8(it.joinToString(",", ",\"unchanged\":[", "]") { name -> "\"$name\"" })
        }
    }

    private fun shortenedField(lists: Map<String, Int>): ByteArray = if (lists.isEmpty()) {
        EMPTY
    } else {
        utf8(lists.entries.joinToString(",", ",\"shortened\":{", "}") { (name, dropped) -> "\"$name\":$dropped" })
    }

    companion object {
        private val NULL = utf8("null")
        private const val NAME = "name"
        private val EMPTY = ByteArray(0)
        private val UNCHANGED_LISTS = ConcurrentHashMap<List<String>, ByteArray>()
        private val CURRENT = utf8(""","current":""")
        private val TAIL = utf8(""","v":$WS_PROTOCOL_VERSION}""")

        /** A change whose states [encode] makes, from which a session cuts fields without encoding them. */
        fun <T : Any> ofMarked(topic: WsTopic, event: ObjectEvent<T>, encode: (T) -> MarkedJson): Change {
            val current by lazy(LazyThreadSafetyMode.NONE) { event.current?.let(encode) }
            return Change(
                topic,
                { event.previous?.let { encode(it).full } },
                { current?.full },
                removed = event.current == null,
                currentWithout = { fields -> current!!.without(fields) },
                currentOnly = { fields -> current!!.only(fields) },
            )
        }

        fun <T : Any> of(topic: WsTopic, event: ObjectEvent<T>, encode: (T) -> ByteArray) = Change(
            topic,
            { event.previous?.let(encode) },
            { event.current?.let(encode) },
            removed = event.current == null,
        )
    }
}

@kotlinx.serialization.Serializable
internal data class NotificationDto(val source: String?, val text: String, val level: String, val timestamp: String)

internal fun UserNotification.toDto() = NotificationDto(source, text, level.name, timestamp.toWire())
