package org.ktcs.kernel.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import java.net.URI
import java.net.http.HttpClient
import java.util.concurrent.TimeUnit

/**
 * The web API on either engine (`web.engine`): Netty by default, where a request is read, handled and answered on the
 * event loop of its connection; CIO as the alternative. A client gets the same answers from both.
 */
class WebEngineTest : FunSpec({
    val http = HttpClient.newHttpClient()
    val order = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}]}"""

    // Status, content type and body of each exchange, with the order's times (which differ between runs) blanked.
    suspend fun answers(vararg settings: String): List<String> {
        val seen = mutableListOf<String>()
        withKernel(*settings) { base ->
            for ((method, path, body) in listOf(
                Triple("POST", "/transportOrders/Same", order),
                Triple("GET", "/transportOrders/Unknown", null),
                Triple("POST", "/transportOrders/Broken", "{\"destinations\":"),
                Triple("GET", "/vehicles/Vehicle-0001", null),
            )) {
                val response = send(http, method, "$base$path", body, json = body != null)
                val type = response.headers().firstValue("Content-Type").orElse("")
                val text = response.body().replace(Regex("\"\\d{4}-\\d\\d-\\d\\dT[^\"]*\""), "\"TIME\"")
                seen += "$method $path: ${response.statusCode()} $type $text"
            }
            val client = RecordingWebSocket()
            http.newWebSocketBuilder().buildAsync(URI(base.replace("http:", "ws:") + "/ws"), client).get()
                .sendText("""{"type":"subscribe"}""", true).get()
            seen += "ws: " + client.messages.poll(10, TimeUnit.SECONDS)
        }
        return seen
    }

    test("by default the web API runs on Netty's event loops") {
        withKernel { base ->
            send(http, "GET", "$base/vehicles").statusCode() shouldBe 200
            Thread.getAllStackTraces().keys.map { it.name.substringBefore('-') } shouldContain "eventLoopGroupProxy"
        }
    }

    test("Netty and CIO give a client the same answers") {
        val netty = answers("web.engine=NETTY")
        netty[0] shouldContain "POST /transportOrders/Same: 200 application/json"
        netty[1] shouldContain ": 404 application/json"
        netty[2] shouldContain ": 400 application/json"
        netty[4] shouldContain "subscribe needs topics"
        answers("web.engine=CIO") shouldBe netty
    }
})
