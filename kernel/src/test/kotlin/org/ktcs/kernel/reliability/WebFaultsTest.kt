package org.ktcs.kernel.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldBeIn
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import java.io.ByteArrayInputStream
import java.net.InetAddress
import java.net.Socket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.net.http.WebSocket
import java.util.concurrent.TimeUnit

/** The web API faults of issue #14, over real HTTP against a running kernel on 127.0.0.1. */
class WebFaultsTest : FunSpec({
    val http = HttpClient.newHttpClient()
    val order = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}]}"""

    test("a name with a character XML cannot carry is refused with 400 naming it, and nothing is created") {
        withKernel { base ->
            for (name in listOf("Ctl-%01x", "Nul-%00x")) {
                val response = send(http, "POST", "$base/transportOrders/$name", order, json = true)
                response.statusCode() shouldBe 400
                response.body() shouldContain "character XML cannot carry: U+00"
            }
            val withProperty = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}],
                "properties":[{"key":"k","value":"a\u0001b"}]}"""
            send(http, "POST", "$base/transportOrders/Prop", withProperty, json = true).body() shouldContain "U+0001"
            send(http, "GET", "$base/transportOrders").body() shouldBe "[]"
        }
    }

    test("a chunked body over the limit gets 413 and creates nothing") {
        withKernel("web.maxRequestBodySize=1") { base ->
            val padding = "x".repeat(3 * 1024 * 1024)
            val body = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}],"type":"$padding"}"""
            val request = HttpRequest.newBuilder(URI("$base/transportOrders/Big"))
                .header("Content-Type", "application/json")
                // An input stream has no known length, so the client sends it chunked, without Content-Length.
                .POST(HttpRequest.BodyPublishers.ofInputStream { ByteArrayInputStream(body.toByteArray()) })
                .build()
            val response = http.send(request, HttpResponse.BodyHandlers.ofString())
            response.statusCode() shouldBe 413
            response.body() shouldStartWith "[\""
            send(http, "GET", "$base/transportOrders/Big").statusCode() shouldBe 404
        }
    }

    test("a malformed chunked body is a 400 and creates nothing, without an ERROR in the log") {
        withKernel { base ->
            val port = URI(base).port
            fun post(chunks: String): String = Socket(InetAddress.getLoopbackAddress(), port).use { socket ->
                socket.soTimeout = 10_000
                socket.getOutputStream().write(
                    (CHUNKED_POST + chunks).toByteArray(),
                )
                socket.getInputStream().readBytes().decodeToString()
            }
            val errors = errorsLoggedWhile {
                // The engine answers these itself, before the request reaches kTCS's routes.
                post("zz\r\n{\r\n0\r\n\r\n") shouldContain " 400 "
                post("10\r\n{\"destinations\":\r\nzz\r\n]}\r\n0\r\n\r\n") shouldContain " 400 "
            }
            errors.shouldBeEmpty()
            send(http, "GET", "$base/transportOrders/Chunky").statusCode() shouldBe 404
        }
    }

    test("a WebSocket frame over the limit closes the connection with 1009; subscribe without topics is answered") {
        withKernel { base ->
            val client = RecordingWebSocket()
            val socket = http.newWebSocketBuilder().buildAsync(URI(base.replace("http:", "ws:") + "/ws"), client).get()
            socket.sendText("""{"type":"subscribe"}""", true).get()
            client.messages.poll(10, TimeUnit.SECONDS)!! shouldContain "subscribe needs topics"
            val errors = errorsLoggedWhile {
                runCatching { socket.sendText("x".repeat(1024 * 1024), true).get(10, TimeUnit.SECONDS) }
                // The server sends 1009 and closes; with the rest of the frame unread, the client may see only the
                // connection reset (-1). Before the limit, the frame was read into memory and nothing closed.
                client.closed.get(10, TimeUnit.SECONDS) shouldBeIn listOf(1009, -1)
            }
            errors.shouldBeEmpty()
        }
    }

    test("WebSocket clients are closed with 1001 when kTCS stops, without an ERROR in the log") {
        val (application, base) = startKernel()
        val client = RecordingWebSocket()
        val socket = http.newWebSocketBuilder().buildAsync(URI(base.replace("http:", "ws:") + "/ws"), client).get()
        // An answer says the server's session runs: the handshake's answer comes before the session is registered.
        socket.sendText("""{"type":"subscribe"}""", true).get()
        client.messages.poll(10, TimeUnit.SECONDS)!! shouldContain "subscribe needs topics"
        val sse = http.sendAsync(
            HttpRequest.newBuilder(URI("$base/sse?/events/vehicles=true")).build(),
            HttpResponse.BodyHandlers.ofLines(),
        )
        sse.get(10, TimeUnit.SECONDS)
        val errors = errorsLoggedWhile { application.stop() }
        client.closed.get(10, TimeUnit.SECONDS) shouldBe 1001
        errors.shouldBeEmpty()
    }

    test("every error the API sends is a JSON array of messages") {
        withKernel { base ->
            for ((method, path) in listOf(
                "PATCH" to "/transportOrders/X",
                "PUT" to "/kernel/version",
                "GET" to "/nope",
            )) {
                val response = send(http, method, "$base$path", null)
                response.body() shouldStartWith "[\""
                response.headers().firstValue("Content-Type").get() shouldStartWith "application/json"
            }
        }
    }
})

private const val CHUNKED_POST = "POST /v1/transportOrders/Chunky HTTP/1.1\r\nHost: 127.0.0.1\r\n" +
    "Content-Type: application/json\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n"
