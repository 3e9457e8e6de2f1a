package org.ktcs.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.net.http.WebSocket
import java.util.concurrent.CompletionStage
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit

/** A client creates 50 orders over HTTP on the demo plant and watches them reach FINISHED on the WebSocket. */
class WebApiEndToEndTest : FunSpec({
    test("50 orders created over HTTP all reach FINISHED, as the WebSocket reports") {
        val settings =
            listOf(
                "web.bindAddress=127.0.0.1",
                "web.port=0",
                "xml.orders.port=0",
                "xml.status.port=0",
                "loopback.timeFactor=50",
            )
        KtcsProcess(*settings.flatMap { listOf("--set", it) }.toTypedArray()).use { ktcs ->
            val base = Regex("web API (http://\\S+)/v1").find(ktcs.awaitLine("kTCS ready"))!!.groupValues[1]
            val http = HttpClient.newHttpClient()
            val finished = ConcurrentHashMap.newKeySet<String>()
            val allFinished = CountDownLatch(1)
            val listener = object : WebSocket.Listener {
                private val text = StringBuilder()

                override fun onText(socket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
                    text.append(data)
                    if (last) {
                        val message = Json.parseToJsonElement(text.toString().also { text.clear() }).jsonObject
                        // A client that falls behind gets "missed" and a fresh snapshot, which then holds the news.
                        val orders = when (message["type"]?.jsonPrimitive?.content) {
                            "event" -> listOfNotNull(message["current"] as? JsonObject)
                            "snapshot" -> message["objects"]!!.jsonArray.map { it.jsonObject }
                            else -> emptyList()
                        }
                        orders.filter { it["state"]?.jsonPrimitive?.content == "FINISHED" }
                            .forEach { finished += it["name"]!!.jsonPrimitive.content }
                        if (finished.count { it.startsWith("E2E-") } == ORDERS) allFinished.countDown()
                    }
                    socket.request(1)
                    return null
                }
            }
            val socket = http.newWebSocketBuilder().buildAsync(
                URI(base.replace("http:", "ws:") + "/v1/ws"),
                listener,
            ).get()
            socket.sendText("""{"type":"subscribe","topics":["transportOrders"]}""", true).get()

            val stations =
                listOf(
                    "Storage 01",
                    "Storage 02",
                    "Goods in north 01",
                    "Goods in north 02",
                    "Goods out 01",
                    "Goods out 02",
                )
            repeat(ORDERS) { index ->
                val from = stations[index % stations.size]
                val to = stations[(index + 2) % stations.size]
                val body = """{"destinations":[{"locationName":"$from","operation":"Load cargo"},""" +
                    """{"locationName":"$to","operation":"Unload cargo"}]}"""
                val request = HttpRequest.newBuilder(URI("$base/v1/transportOrders/E2E-$index"))
                    .header("Content-Type", "application/json")
                    .POST(HttpRequest.BodyPublishers.ofString(body))
                    .build()
                http.send(request, HttpResponse.BodyHandlers.ofString()).statusCode() shouldBe 200
            }

            allFinished.await(240, TimeUnit.SECONDS)
            withClue({ "orders not FINISHED by the WebSocket's account: " + unfinished(http, base, finished) }) {
                finished.count { it.startsWith("E2E-") } shouldBe ORDERS
            }
            socket.abort()
            ktcs.terminate() shouldBe 0
        }
    }
})

private const val ORDERS = 50

// What the kernel says about the orders the WebSocket did not report as finished, for the failure message.
private fun unfinished(http: HttpClient, base: String, finished: Set<String>): String {
    val request = HttpRequest.newBuilder(URI("$base/v1/transportOrders")).build()
    val orders = Json.parseToJsonElement(http.send(request, HttpResponse.BodyHandlers.ofString()).body()).jsonArray
    return orders.map { it.jsonObject }
        .filter { it["name"]!!.jsonPrimitive.content !in finished }
        .joinToString { order ->
            val vehicle = order["processingVehicle"]?.takeUnless { it is JsonNull }?.jsonPrimitive?.content
            "${order["name"]!!.jsonPrimitive.content} ${order["state"]!!.jsonPrimitive.content} vehicle=$vehicle"
        }
}
