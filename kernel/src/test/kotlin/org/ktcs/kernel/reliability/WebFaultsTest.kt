package org.ktcs.kernel.reliability

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldBeIn
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.extension.KtcsExtension
import org.slf4j.LoggerFactory
import java.io.ByteArrayInputStream
import java.net.InetAddress
import java.net.Socket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.net.http.WebSocket
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CompletionStage
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
                // The engine (CIO) answers these itself, before the request reaches kTCS's routes.
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
        http.newWebSocketBuilder().buildAsync(URI(base.replace("http:", "ws:") + "/ws"), client).get()
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

/** The cross-site rules of issue #14: what a web page in a browser on the kTCS host may and may not do. */
class CrossSiteRequestsTest : FunSpec({
    val http = HttpClient.newHttpClient()
    val order = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}]}"""
    val evil = "http://evil.example"

    test("a text/plain POST (a form or a simple fetch from any page) creates nothing") {
        withKernel { base ->
            val response =
                send(
                    http,
                    "POST",
                    "$base/transportOrders/Evil",
                    order,
                    headers = mapOf("Content-Type" to "text/plain", "Origin" to evil),
                )
            response.statusCode() shouldBe 415
            send(
                http,
                "POST",
                "$base/transportOrders/Plain",
                order,
                headers = mapOf("Content-Type" to "text/plain"),
            ).statusCode() shouldBe
                415
            send(http, "GET", "$base/transportOrders").body() shouldBe "[]"
        }
    }

    test("a page from another origin can change nothing, even without a body; programs and kTCS's own pages can") {
        withKernel { base ->
            val host = URI(base).authority
            val fromEvil = mapOf("Origin" to evil, "Sec-Fetch-Site" to "cross-site")
            send(http, "POST", "$base/dispatcher/trigger", null, headers = fromEvil).statusCode() shouldBe 403
            send(
                http,
                "PUT",
                "$base/vehicles/Vehicle-01/paused?newValue=true",
                null,
                headers = fromEvil,
            ).statusCode() shouldBe
                403
            send(
                http,
                "POST",
                "$base/transportOrders/E",
                order,
                json = true,
                headers = mapOf("Origin" to evil),
            ).statusCode() shouldBe
                403
            send(http, "POST", "$base/dispatcher/trigger", null).statusCode() shouldBe 200
            val own = mapOf("Origin" to "http://$host", "Sec-Fetch-Site" to "same-origin", "X-Requested-With" to "kTCS")
            send(http, "POST", "$base/transportOrders/Own", order, json = true, headers = own).statusCode() shouldBe 200
            send(
                http,
                "POST",
                "$base/dispatcher/trigger",
                null,
                headers = mapOf("Origin" to "http://$host"),
            ).statusCode() shouldBe
                403
        }
    }

    test("CORS allows only the origins configured; none by default") {
        withKernel { base ->
            send(http, "GET", "$base/vehicles", null, headers = mapOf("Origin" to evil)).headers()
                .firstValue("Access-Control-Allow-Origin").isPresent shouldBe false
            send(
                http,
                "OPTIONS",
                "$base/transportOrders/T",
                null,
                headers = mapOf("Origin" to evil),
            ).statusCode() shouldBe
                403
        }
        withKernel("web.allowedOrigins=https://mes.example") { base ->
            val preflight =
                send(
                    http,
                    "OPTIONS",
                    "$base/transportOrders/T",
                    null,
                    headers = mapOf("Origin" to "https://mes.example"),
                )
            preflight.statusCode() shouldBe 200
            preflight.headers().firstValue("Access-Control-Allow-Origin").get() shouldBe "https://mes.example"
        }
    }

    test("the WebSocket refuses pages from other origins") {
        withKernel { base ->
            val ws = URI(base.replace("http:", "ws:") + "/ws")
            val refused =
                runCatching {
                    http.newWebSocketBuilder().header("Origin", evil).buildAsync(ws, RecordingWebSocket()).get()
                }
            refused.isFailure shouldBe true
            val host = URI(base).authority
            http.newWebSocketBuilder().header(
                "Origin",
                "http://$host",
            ).buildAsync(ws, RecordingWebSocket()).get().abort()
        }
    }

    test("DELETE /v1/kernel needs the access key or web.allowLocalShutdown, even from this machine") {
        withKernel { base ->
            val response = send(http, "DELETE", "$base/kernel", null)
            response.statusCode() shouldBe 403
            response.body() shouldContain "web.allowLocalShutdown"
        }
        withKernel("web.accessKey=secret") { base ->
            send(
                http,
                "DELETE",
                "$base/kernel",
                null,
                headers = mapOf("X-Api-Access-Key" to "secret"),
            ).statusCode() shouldBe
                200
        }
        withKernel("web.allowLocalShutdown=true") { base ->
            send(http, "DELETE", "$base/kernel", null).statusCode() shouldBe 200
        }
    }
})

private const val CHUNKED_POST = "POST /v1/transportOrders/Chunky HTTP/1.1\r\nHost: 127.0.0.1\r\n" +
    "Content-Type: application/json\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n"

private val stepVehicles = object : KtcsExtension {
    override val name = "step-vehicles"

    override fun module(): Module = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
}

/** A kernel with the demo plant and its web API on 127.0.0.1, and the base URL of its `/v1`. */
fun startKernel(vararg settings: String): Pair<KernelApplication, String> {
    val config = ConfigLoader().load(null, emptyMap(), listOf("web.bindAddress=127.0.0.1", "web.port=0") + settings)
    val application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(stepVehicles)) {}
    val base = Regex("web API (http://\\S+/v1)").find(application.start())!!.groupValues[1]
    return application to base
}

suspend fun withKernel(vararg settings: String, block: suspend (String) -> Unit) {
    val (application, base) = startKernel(*settings)
    try {
        block(base)
    } finally {
        application.stop()
    }
}

fun send(
    http: HttpClient,
    method: String,
    url: String,
    body: String? = null,
    json: Boolean = false,
    headers: Map<String, String> = emptyMap(),
): HttpResponse<String> {
    val publisher = body?.let(HttpRequest.BodyPublishers::ofString) ?: HttpRequest.BodyPublishers.noBody()
    val request = HttpRequest.newBuilder(URI(url)).method(method, publisher)
    if (json) request.header("Content-Type", "application/json")
    headers.forEach { (name, value) -> request.header(name, value) }
    return http.send(request.build(), HttpResponse.BodyHandlers.ofString())
}

/** ERROR lines any logger writes while [block] runs. */
suspend fun errorsLoggedWhile(block: suspend () -> Unit): List<String> {
    val root = LoggerFactory.getLogger(Logger.ROOT_LOGGER_NAME) as Logger
    val appender = ListAppender<ILoggingEvent>().apply { start() }
    root.addAppender(appender)
    try {
        block()
    } finally {
        root.detachAppender(appender)
    }
    return appender.list.filter { it.level == Level.ERROR }.map { "${it.loggerName}: ${it.formattedMessage}" }
}

/** A WebSocket listener that records text messages and the close code (or -1 when the connection failed). */
class RecordingWebSocket : WebSocket.Listener {
    val messages = java.util.concurrent.LinkedBlockingQueue<String>()
    val closed = CompletableFuture<Int>()

    override fun onText(webSocket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
        messages.put(data.toString())
        webSocket.request(1)
        return null
    }

    override fun onClose(webSocket: WebSocket, statusCode: Int, reason: String): CompletionStage<*>? {
        closed.complete(statusCode)
        return null
    }

    override fun onError(webSocket: WebSocket, error: Throwable) {
        closed.complete(-1)
    }
}
