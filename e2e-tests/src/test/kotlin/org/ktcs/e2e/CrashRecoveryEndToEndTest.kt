package org.ktcs.e2e

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.ints.shouldBeGreaterThan
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import java.time.Duration
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger

/**
 * `./ktcs` with the embedded store, 200 orders flowing from 8 clients, killed with SIGKILL midway, started again:
 * every order it accepted (HTTP 2xx) is there once and finishes, and no resource is ever held by two vehicles.
 */
class CrashRecoveryEndToEndTest : FunSpec({
    test("after kill -9 and a restart every accepted order is there once and finishes, nothing allocated twice") {
        val data = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-crash")
        val accepted = ConcurrentHashMap.newKeySet<String>()
        val first = start(data)
        val firstBase = baseOf(first)
        val sent = AtomicInteger()
        val clients = Executors.newFixedThreadPool(CLIENTS)
        repeat(CLIENTS) { client ->
            clients.execute {
                for (index in client until ORDERS step CLIENTS) {
                    val name = "Crash-%03d".format(index)
                    if (post(firstBase, name)) accepted += name
                    sent.incrementAndGet()
                }
            }
        }
        // Killed while orders are still coming in and vehicles are under way.
        while (sent.get() < ORDERS / 2) Thread.sleep(5)
        first.kill()
        clients.shutdown()
        clients.awaitTermination(60, TimeUnit.SECONDS)
        accepted.size shouldBeGreaterThan 0

        start(data).use { second ->
            val base = baseOf(second)
            val recovered = second.output().lines().firstOrNull { "state recovered" in it }
            println("crash test: ${accepted.size} of $ORDERS orders accepted before kill -9; $recovered")
            val doubleAllocations = mutableListOf<String>()
            val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(FINISH_SECONDS)
            var orders: List<JsonObject>
            do {
                doubleAllocations += sharedResources(base)
                orders = getArray("$base/v1/transportOrders")
                val open = orders.filter { it.string("name") in accepted && !it.isFinal() }
                if (open.isEmpty() && orders.map { it.string("name") }.containsAll(accepted)) break
                Thread.sleep(POLL_MILLIS)
            } while (System.nanoTime() < deadline)

            val names = orders.map { it.string("name") }
            withClue(second.output().lines().takeLast(40).joinToString("\n")) {
                (accepted - names.toSet()).shouldBeEmpty()
                names.groupingBy { it }.eachCount().filterValues { it > 1 }.keys.shouldBeEmpty()
                orders.filter { it.string("name") in accepted }.filter { it.string("state") != "FINISHED" }
                    .map { "${it.string("name")}: ${it.string("state")}" }.shouldBeEmpty()
                doubleAllocations.shouldBeEmpty()
            }
        }
    }
})

private const val CLIENTS = 8
private const val ORDERS = 200
private const val FINISH_SECONDS = 150L
private const val POLL_MILLIS = 100L
private val http: HttpClient = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(2)).build()
private val stations = listOf("Storage 01" to "Goods out 01", "Storage 02" to "Goods out 02")

private fun start(data: Path) = KtcsProcess(
    *listOf(
        "web.bindAddress=127.0.0.1",
        "web.port=0",
        "xml.orders.port=0",
        "xml.status.port=0",
        "loopback.timeFactor=100",
        "kernel.dataDirectory=$data",
        "persistence.durability=COMMIT",
    ).flatMap { listOf("--set", it) }.toTypedArray(),
)

private fun baseOf(ktcs: KtcsProcess) =
    Regex("web API (http://\\S+)/v1").find(ktcs.awaitLine("kTCS ready"))!!.groupValues[1]

private fun post(base: String, name: String): Boolean {
    val (from, to) = stations[name.takeLast(1).toInt() % stations.size]
    val body = """{"destinations":[{"locationName":"$from","operation":"Load cargo"},""" +
        """{"locationName":"$to","operation":"Unload cargo"}]}"""
    val request = HttpRequest.newBuilder(URI("$base/v1/transportOrders/$name"))
        .header("Content-Type", "application/json")
        .timeout(Duration.ofSeconds(10))
        .POST(HttpRequest.BodyPublishers.ofString(body))
        .build()
    return try {
        http.send(request, HttpResponse.BodyHandlers.discarding()).statusCode() in 200..299
    } catch (_: java.io.IOException) {
        false // the kernel was killed before it answered: not accepted
    }
}

private fun getArray(url: String): List<JsonObject> {
    val response = http.send(HttpRequest.newBuilder(URI(url)).build(), HttpResponse.BodyHandlers.ofString())
    return Json.parseToJsonElement(response.body()).jsonArray.map { it.jsonObject }
}

/** Resources that two vehicles hold at once, as the web API shows them now. */
private fun sharedResources(base: String): List<String> {
    val holders = HashMap<String, String>()
    return getArray("$base/v1/vehicles").flatMap { vehicle ->
        val name = vehicle.string("name")
        vehicle["allocatedResources"]!!.jsonArray.flatMap { it.jsonArray.map { r -> r.jsonPrimitive.content } }
            .distinct()
            .mapNotNull { resource -> holders.put(resource, name)?.let { "$resource: $it and $name" } }
    }
}

private fun JsonObject.string(key: String) = this[key]!!.jsonPrimitive.content

private fun JsonObject.isFinal() = string("state") in setOf("FINISHED", "FAILED", "UNROUTABLE")
