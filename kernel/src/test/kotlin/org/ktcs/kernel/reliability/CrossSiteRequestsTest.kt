package org.ktcs.kernel.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import java.net.URI
import java.net.http.HttpClient
import java.net.http.WebSocket

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
