package org.ktcs.e2e.plant

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.URI
import java.net.http.HttpClient
import java.net.http.WebSocket
import java.util.concurrent.CompletionStage
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.TimeUnit

/**
 * Follows the plant on kTCS's WebSocket (`/v1/ws`, topics vehicles and transportOrders): the latest state of every
 * order, which vehicles processed orders, and every moment a resource was allocated to two vehicles at once,
 * checked after each event in kernel order.
 */
class PlantFollower(webBase: String) : AutoCloseable {
    private val ledger = AllocationLedger()
    private val orderStates = ConcurrentHashMap<String, String>()
    private val processors = ConcurrentHashMap<String, String>()
    val doubleAllocations: MutableList<String> = CopyOnWriteArrayList()
    val errors: MutableList<String> = CopyOnWriteArrayList()

    @Volatile var eventCount = 0
        private set
    private val snapshots = java.util.concurrent.CountDownLatch(2)

    private val socket: WebSocket = HttpClient.newHttpClient().newWebSocketBuilder()
        .buildAsync(URI("${webBase.replaceFirst("http", "ws")}/v1/ws"), Listener())
        .get(10, TimeUnit.SECONDS)
        .also { it.sendText("""{"type":"subscribe","topics":["vehicles","transportOrders"]}""", true) }

    /** Waits for both snapshots, so that no later change is missed. */
    fun awaitSnapshots() = check(snapshots.await(10, TimeUnit.SECONDS)) { "no WebSocket snapshots within 10 s" }

    fun stateOf(order: String): String? = orderStates[order]

    /** The vehicle that processed [order], once one did. */
    fun processorOf(order: String): String? = processors[order]

    override fun close() {
        socket.sendClose(WebSocket.NORMAL_CLOSURE, "done")
    }

    @Synchronized
    private fun handle(message: JsonObject) {
        val type = message["type"]?.jsonPrimitive?.content
        val topic = message["topic"]?.jsonPrimitive?.content
        when (type) {
            "snapshot" -> {
                message["objects"]!!.jsonArray.forEach { update(topic, it.jsonObject) }
                snapshots.countDown()
            }

            "event" -> {
                eventCount++
                (message["current"] as? JsonObject)?.let { update(topic, it) }
            }

            else -> errors += "unexpected WebSocket message: $message"
        }
    }

    private fun update(topic: String?, current: JsonObject) {
        val name = current["name"]!!.jsonPrimitive.content
        when (topic) {
            "transportOrders" -> {
                orderStates[name] = current["state"]!!.jsonPrimitive.content
                current["processingVehicle"]?.takeIf { it !is kotlinx.serialization.json.JsonNull }
                    ?.let { processors[name] = it.jsonPrimitive.content }
            }

            "vehicles" -> {
                val resources = (current["allocatedResources"] as JsonArray)
                    .flatMap { step -> step.jsonArray.map { it.jsonPrimitive.content } }.toSet()
                ledger.update(name, resources).forEach { doubleAllocations += "after event $eventCount: $it" }
            }
        }
    }

    private inner class Listener : WebSocket.Listener {
        private val text = StringBuilder()

        override fun onText(webSocket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
            text.append(data)
            if (last) {
                handle(Json.parseToJsonElement(text.toString()).jsonObject)
                text.clear()
            }
            webSocket.request(1)
            return null
        }

        override fun onError(webSocket: WebSocket, error: Throwable) {
            errors += "WebSocket failed: $error"
        }
    }
}
