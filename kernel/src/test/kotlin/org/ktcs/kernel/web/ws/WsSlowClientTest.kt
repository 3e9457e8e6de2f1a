package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.web.WebApiClient
import org.ktcs.kernel.web.checkedWsMessage
import java.net.URI

/**
 * A WebSocket client that stops reading while orders pour in: the kernel and HTTP clients carry on, and when the
 * client reads again it is told it missed events and gets a snapshot with everything.
 */
class WsSlowClientTest : FunSpec({
    test("a client that falls behind is told it missed events, then gets a complete snapshot") {
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf("web.bindAddress=127.0.0.1", "web.port=0", "web.webSocketBufferSize=20"),
        )
        val application = KernelApplication(config, PlantModelLoader.loadDemo(), emptyList())
        val base = Regex("web API (http://\\S+/v1)").find(application.start())!!.groupValues[1]
        try {
            val socket = RawWebSocket(URI(base.replace("http:", "ws:") + "/ws"))
            fun next(): JsonObject = checkedWsMessage(socket.receiveText())
            socket.sendText("""{"type":"subscribe","topics":["transportOrders"]}""")
            next().text("type") shouldBe "snapshot"

            // The client stops reading. Big orders, so that the events fill the socket buffers and then its queue of 20.
            val payload = "x".repeat(50_000)
            val client = WebApiClient()
            val names = (1..100).map { "Slow-$it" }
            names.forEach { name ->
                val body = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}],""" +
                    """"properties":[{"key":"payload","value":"$payload"}]}"""
                client.call("POST", "$base/transportOrders/$name", body).statusCode() shouldBe 200
            }

            // It reads again: everything it missed comes as snapshots, each announced by "missed".
            val messages = generateSequence {
                socket.receiveTextOrNull(quietMillis = 3_000)
            }.map(::checkedWsMessage).toList()
            val types = messages.map { it.text("type") }
            types shouldContain "missed"
            types.zipWithNext().filter { (type, _) ->
                type == "missed"
            }.forEach { (_, next) -> next shouldBe "snapshot" }
            val known = messages.flatMap { message ->
                when (message.text("type")) {
                    "snapshot" -> message["objects"]!!.jsonArray.map { it.jsonObject.text("name") }
                    "event" -> listOf(message["current"]!!.jsonObject.text("name"))
                    else -> emptyList()
                }
            }
            known shouldContainAll names
            socket.close()
        } finally {
            application.stop()
        }
    }
})

private fun JsonObject.text(key: String) = this[key]!!.jsonPrimitive.content
