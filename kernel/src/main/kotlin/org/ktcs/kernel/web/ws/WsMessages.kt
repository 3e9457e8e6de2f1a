package org.ktcs.kernel.web.ws

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement

/** The version of the WebSocket protocol; it is in every message the server sends. */
const val WS_PROTOCOL_VERSION = 1

/**
 * What a client may say: which topics it wants. Unknown topics are refused with an error message. With [previous]
 * `false` events carry the previous state only for a removed object (else `null`): a client that keeps the latest
 * state of each object needs no more, and the stream is half as long. With [omitUnchanged] an event's `current` leaves
 * out the large fields that did not change (an order's drive orders, a vehicle's claimed and allocated resources, ...)
 * and names them in [WsEvent.unchanged]: the client keeps them from the object's state before. With [shortenedLists]
 * as well, a vehicle's resource list that is the list before without its first entries is left out too and
 * [WsEvent.shortened] says how many entries the client drops from the front of the list it has. With [onlyChanged], an
 * event's `current` of a vehicle or transport order that was there before has its `name` and only the fields whose
 * values changed (a field that became `null` is sent as `null`), and no `unchanged` list: the client merges it into
 * the state it has. A driving vehicle's event is then a few dozen bytes of its own.
 */
@Serializable
data class WsClientMessage(
    val type: String,
    val topics: List<String> = emptyList(),
    val previous: Boolean = true,
    val omitUnchanged: Boolean = false,
    val shortenedLists: Boolean = false,
    val onlyChanged: Boolean = false,
)

/** What the server says. */
@Serializable
sealed interface WsServerMessage {
    val v: Int
}

/** Everything of [topic] as it is now; sent on subscribe and after the client missed events. */
@Serializable
@SerialName("snapshot")
data class WsSnapshot(
    val topic: String,
    val objects: List<JsonElement>,
    override val v: Int = WS_PROTOCOL_VERSION,
) : WsServerMessage

/**
 * One change, in kernel order: [previous] is `null` for a new object, [current] for a removed one. [unchanged] names the
 * fields left out of [current] because they are as before (only for a client that subscribed with `omitUnchanged`);
 * [shortened] the lists left out because they are the lists before without that many entries at their front (only
 * for a client that subscribed with `shortenedLists`).
 */
@Serializable
@SerialName("event")
data class WsEvent(
    val topic: String,
    val seq: Long,
    val previous: JsonElement?,
    val current: JsonElement?,
    @OptIn(ExperimentalSerializationApi::class)
    @EncodeDefault(EncodeDefault.Mode.NEVER)
    val unchanged: List<String>? = null,
    @OptIn(ExperimentalSerializationApi::class)
    @EncodeDefault(EncodeDefault.Mode.NEVER)
    val shortened: Map<String, Int>? = null,
    override val v: Int = WS_PROTOCOL_VERSION,
) : WsServerMessage

/** The client fell behind and events were dropped; fresh snapshots of its topics follow. */
@Serializable
@SerialName("missed")
data class WsMissed(val reason: String, override val v: Int = WS_PROTOCOL_VERSION) : WsServerMessage

/** The plant model was replaced (`PUT /v1/plantModel`); fresh snapshots of the client's topics follow. */
@Serializable
@SerialName("modelReplaced")
data class WsModelReplaced(val name: String, override val v: Int = WS_PROTOCOL_VERSION) : WsServerMessage

/** The client sent something the server does not understand. */
@Serializable
@SerialName("error")
data class WsError(val message: String, override val v: Int = WS_PROTOCOL_VERSION) : WsServerMessage

/** The topics a client can subscribe to. */
enum class WsTopic(val wireName: String) {
    VEHICLES("vehicles"),
    TRANSPORT_ORDERS("transportOrders"),
    ORDER_SEQUENCES("orderSequences"),
    PLANT_MODEL("plantModel"),
    NOTIFICATIONS("notifications"),
    DRIVER_EVENTS("driverEvents"),
    ;

    companion object {
        fun of(name: String): WsTopic? = entries.firstOrNull { it.wireName == name }
    }
}
