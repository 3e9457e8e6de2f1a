package org.ktcs.e2e

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.InetAddress
import java.net.ServerSocket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds

/**
 * `./ktcs` with the VDA 5050 demo plant, whose four vehicles are VDA 5050 vehicles that `./ktcs vda5050-sim` plays
 * over kTCS's embedded MQTT broker: 20 orders created over HTTP all reach FINISHED.
 */
class Vda5050EndToEndTest : FunSpec({
    test("20 orders on VDA 5050 vehicles played by the simulator over the embedded broker all finish") {
        val broker = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }
        val plant = RepositoryRoot.path
            .resolve("adapters-vda5050/src/main/resources/org/ktcs/adapters/vda5050/demo/vda5050-demo.xml")
        val settings = listOf(
            "web.bindAddress=127.0.0.1",
            "web.port=0",
            "xml.orders.port=0",
            "xml.status.port=0",
            "vda5050.embeddedBroker.port=$broker",
            "kernel.dataDirectory=${Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-vda-e2e")}",
        )
        KtcsProcess("--model", plant.toString(), *settings.flatMap { listOf("--set", it) }.toTypedArray()).use { ktcs ->
            val base = Regex("web API (http://\\S+)/v1").find(ktcs.awaitLine("kTCS ready"))!!.groupValues[1]
            KtcsProcess("vda5050-sim", "--broker", "tcp://127.0.0.1:$broker", "--time-factor", "20").use { sim ->
                sim.awaitLine("playing SIM-01, SIM-02, SIM-03, SIM-04")
                val http = HttpClient.newHttpClient()
                fun get(path: String) = http.send(
                    HttpRequest.newBuilder(URI("$base/v1$path")).build(),
                    HttpResponse.BodyHandlers.ofString(),
                ).body()
                eventually(30.seconds) {
                    Json.parseToJsonElement(get("/vehicles")).jsonArray
                        .map { it.jsonObject["state"]!!.jsonPrimitive.content }.toSet() shouldBe setOf("IDLE")
                }
                val stations = listOf("Storage 01", "Storage 02", "Goods out 01", "Goods out 02", "Goods in north 01")
                repeat(VDA_ORDERS) { i ->
                    val body = """{"destinations":[""" +
                        """{"locationName":"${stations[i % 5]}","operation":"Load cargo"},""" +
                        """{"locationName":"${stations[(i + 2) % 5]}","operation":"Unload cargo"}]}"""
                    val response = http.send(
                        HttpRequest.newBuilder(URI("$base/v1/transportOrders/VDA-$i"))
                            .header("Content-Type", "application/json")
                            .POST(HttpRequest.BodyPublishers.ofString(body)).build(),
                        HttpResponse.BodyHandlers.ofString(),
                    )
                    response.statusCode() shouldBe 200
                }
                eventually(240.seconds) {
                    val states = Json.parseToJsonElement(get("/transportOrders")).jsonArray.map { it.jsonObject }
                        .filter { it["name"]!!.jsonPrimitive.content.startsWith("VDA-") }
                        .groupingBy { it["state"]!!.jsonPrimitive.content }.eachCount()
                    states shouldBe mapOf("FINISHED" to VDA_ORDERS)
                }
            }
        }
    }
})

private const val VDA_ORDERS = 20
