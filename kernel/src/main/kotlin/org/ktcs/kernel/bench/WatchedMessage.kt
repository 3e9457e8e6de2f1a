package org.ktcs.kernel.bench

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive

/**
 * A message of kTCS's WebSocket with only the fields the bench reads: decoding into these skips the rest of each
 * object without building a tree of it, which keeps the bench's share of the machine it shares with kTCS small.
 */
@Serializable
internal class WatchedMessage(
    val type: String? = null,
    val topic: String? = null,
    val objects: List<Observed> = emptyList(),
    val previous: Observed? = null,
    val current: Observed? = null,
    val shortened: Map<String, Int> = emptyMap(),
) {
    /**
     * A vehicle, order or notification: `state` is a vehicle's object or an order's string; `allocatedResources` is
     * `null` where an event left them out as unchanged; `currentPosition` is [JsonNull] for a vehicle on no point and
     * [NOT_SENT] where the event left it out (kotlinx reads a `null` as a missing value for a nullable property).
     */
    @Serializable
    class Observed(
        val name: String? = null,
        val state: JsonElement? = null,
        val currentPosition: JsonElement = NOT_SENT,
        val allocatedResources: List<List<String>>? = null,
        val text: String? = null,
        val source: String? = null,
    ) {
        /** Whether the event says where the vehicle is (a point or none): it leaves that out when it did not change. */
        val sendsPosition: Boolean get() = currentPosition !== NOT_SENT

        /** The point the vehicle is on, if the event [sendsPosition] and it is on one. */
        val point: String? get() = (currentPosition as? JsonPrimitive)?.takeIf { it.isString }?.content

        /** A notification of a deadlock the watchdog found. */
        val isDeadlock: Boolean get() = text?.startsWith("deadlock") == true

        /** A notification of the watchdog's that is no deadlock: an idle vehicle in another's way was sent off it. */
        val isIdleVehicleMoved: Boolean get() = !isDeadlock && source == "deadlock watchdog"
    }

    companion object {
        /** The value of a field an event left out. */
        val NOT_SENT: JsonElement = JsonObject(emptyMap())

        private val json = Json { ignoreUnknownKeys = true }

        /** [text] as a message, or `null` if it is none. */
        fun parse(text: String): WatchedMessage? =
            runCatching { json.decodeFromString(serializer(), text) }.getOrNull()
    }
}
