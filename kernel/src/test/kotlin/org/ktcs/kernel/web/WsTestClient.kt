package org.ktcs.kernel.web

import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import org.ktcs.kernel.web.contract.WebApiContracts
import java.net.URI
import java.net.http.HttpClient
import java.net.http.WebSocket
import java.util.concurrent.CompletionStage
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/**
 * A client of `/v1/ws` for the web API tests, at [base] (`http://host:port/v1`). It reads every message as soon as it
 * arrives; each is checked against kTCS's `WsServerMessage` schema before the test sees it.
 */
class WsTestClient(http: HttpClient, base: String) : AutoCloseable {
    private val received = LinkedBlockingQueue<String>()
    private val listener = object : WebSocket.Listener {
        private val partial = StringBuilder()

        override fun onText(socket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
            partial.append(data)
            if (last) received.put(partial.toString()).also { partial.clear() }
            socket.request(1)
            return null
        }
    }
    private val socket = http.newWebSocketBuilder().buildAsync(
        URI(base.replace("http:", "ws:") + "/ws"),
        listener,
    ).get()

    fun send(text: String) {
        socket.sendText(text, true).get()
    }

    /** The next message, waiting up to 10 s. */
    fun next(): JsonObject = checkedWsMessage(
        received.poll(10, TimeUnit.SECONDS) ?: error("no WebSocket message in 10 s"),
    )

    override fun close() {
        socket.abort()
    }
}

/** [message] parsed, after checking it against kTCS's `WsServerMessage` schema. */
fun checkedWsMessage(message: String): JsonObject {
    WebApiContracts.ktcs.violationsOf(pointer = "/components/schemas/WsServerMessage", json = message) shouldBe
        emptyList()
    return Json.parseToJsonElement(message).jsonObject
}
