package org.ktcs.kernel.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.time.Duration
import java.util.concurrent.TimeUnit

/**
 * Seeded fuzzing of the web API (issue #14): generated requests over its operations, with bodies, names and
 * parameters from a grammar of plausible and hostile values. Every answer must be below 500 and every error a JSON
 * array of messages; only requests answered 200 may create anything; the API and its WebSocket work afterwards.
 */
class RestFuzzTest : FunSpec({
    test("$CASES generated requests: no 5xx, every error openTCS's shape, nothing created by invalid input") {
        val http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build()
        withKernel("web.maxRequestBodySize=1") { base ->
            val generator = RestCaseGenerator(SEED)
            val outcome = FuzzOutcome()
            repeat(CASES) {
                val case = generator.next()
                val response = runCatching { case.send(http, base) }
                outcome.record(case, response)
            }
            outcome.checkCreated(http, base)
            println("rest fuzz (seed $SEED): ${outcome.summary()}")
            outcome.failures.take(20).forEach { println("rest fuzz failure: $it") }
            checkStillServing(http, base)
            outcome.failures.shouldBeEmpty()
            outcome.tried shouldBe CASES
            outcome.handled shouldBeGreaterThanOrEqual CASES
        }
    }
}) {
    companion object {
        const val SEED = 14L
        const val CASES = 1_200
    }
}

/** What the fuzz run saw: counts by status and every failure, described. */
private class FuzzOutcome {
    var tried = 0
    var handled = 0
    val byStatus = sortedMapOf<Int, Int>()
    val failures = mutableListOf<String>()
    val createdOrders = mutableSetOf<String>()
    val createdSequences = mutableSetOf<String>()

    fun record(case: RestCase, result: Result<HttpResponse<String>>) {
        tried++
        val response = result.getOrElse {
            failures += "$case: no answer (${it.javaClass.simpleName}: ${it.message})"
            return
        }
        val status = response.statusCode()
        byStatus.merge(status, 1, Int::plus)
        when {
            status >= 500 -> failures += "$case: $status ${response.body().take(200)}"

            // A HEAD answer never has a body; its status is all there is to check.
            case.method == "HEAD" -> handled++

            status >= 400 && !isErrorArray(response) ->
                failures +=
                    "$case: $status not a JSON array: ${response.body().take(200)}"

            else -> {
                handled++
                if (status == 200) noteCreated(case, response)
            }
        }
    }

    private fun noteCreated(case: RestCase, response: HttpResponse<String>) {
        if (case.method != "POST") return
        val name = runCatching { Json.parseToJsonElement(response.body()).jsonObject["name"]!!.jsonPrimitive.content }
            .getOrNull() ?: return
        when {
            case.path.startsWith("/transportOrders/") && case.path.count { it == '/' } == 2 -> createdOrders += name
            case.path.startsWith("/orderSequences/") && case.path.count { it == '/' } == 2 -> createdSequences += name
        }
    }

    private fun isErrorArray(response: HttpResponse<String>): Boolean {
        if (response.headers().firstValue("Content-Type").orElse("").startsWith("application/json").not()) return false
        val parsed = runCatching { Json.parseToJsonElement(response.body()) }.getOrNull() as? JsonArray ?: return false
        return parsed.isNotEmpty() && parsed.all { it is JsonPrimitive && it.isString && it.content.isNotBlank() }
    }

    /** The kernel holds exactly the orders and sequences whose creation was answered 200. */
    fun checkCreated(http: HttpClient, base: String) {
        val orders = names(http, "$base/transportOrders")
        val sequences = names(http, "$base/orderSequences")
        if (orders != createdOrders) {
            failures +=
                "orders created without a 200: ${orders - createdOrders}, lost: ${createdOrders - orders}"
        }
        if (sequences != createdSequences) {
            failures +=
                "sequences created without a 200: ${sequences - createdSequences}, lost: ${createdSequences - sequences}"
        }
    }

    private fun names(http: HttpClient, url: String): Set<String> =
        Json.parseToJsonElement(send(http, "GET", url).body()).jsonArray
            .map { it.jsonObject["name"]!!.jsonPrimitive.content }.toSet()

    fun summary() = "cases tried $tried, handled $handled (by status $byStatus), failures ${failures.size}, " +
        "orders created ${createdOrders.size}, sequences created ${createdSequences.size}"
}

/** After the fuzzing, a valid order is created and the WebSocket answers a subscription with a snapshot. */
private fun checkStillServing(http: HttpClient, base: String) {
    val order = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"}]}"""
    send(http, "POST", "$base/transportOrders/After-fuzz", order, json = true).statusCode() shouldBe 200
    val client = RecordingWebSocket()
    val socket = http.newWebSocketBuilder().buildAsync(URI(base.replace("http:", "ws:") + "/ws"), client).get()
    socket.sendText("""{"type":"subscribe","topics":["vehicles"]}""", true).get()
    (client.messages.poll(10, TimeUnit.SECONDS) ?: "").contains("\"snapshot\"") shouldBe true
    socket.abort()
}

/** One generated request. */
class RestCase(
    val method: String,
    val path: String,
    val body: String?,
    val contentType: String?,
    val headers: Map<String, String> = emptyMap(),
) {
    fun send(http: HttpClient, base: String): HttpResponse<String> {
        val publisher = body?.let(HttpRequest.BodyPublishers::ofString) ?: HttpRequest.BodyPublishers.noBody()
        val request = HttpRequest.newBuilder(URI(base + path)).timeout(Duration.ofSeconds(15)).method(method, publisher)
        contentType?.let { request.header("Content-Type", it) }
        headers.forEach { (name, value) -> request.header(name, value) }
        return http.send(request.build(), HttpResponse.BodyHandlers.ofString())
    }

    override fun toString() = "$method $path [${contentType ?: "no type"}] ${body?.take(120) ?: ""}"
}
