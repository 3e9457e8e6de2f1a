package org.ktcs.kernel.web

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldNotContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.web.contract.WebApiContracts
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.seconds

/** The web API v1 of a running kernel, over real HTTP: happy paths, bad input, 404, 409, the access key. */
class WebApiTest : FunSpec({
    val testVehicles = object : KtcsExtension {
        override val name = "step-vehicles"

        override fun module(): Module = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
    }
    val client = WebApiClient()
    val http = client.http

    val shutdownRequests = AtomicInteger()

    fun start(vararg settings: String): Pair<KernelApplication, String> {
        val base = listOf("web.bindAddress=127.0.0.1", "web.port=0", "kernel.dataDirectory=${tempdir()}")
        val config = ConfigLoader().load(null, emptyMap(), base + settings)
        val application =
            KernelApplication(config, PlantModelLoader.loadDemo(), listOf(testVehicles)) {
                shutdownRequests.incrementAndGet()
            }
        val url = Regex("web API (http://\\S+/v1)").find(application.start())!!.groupValues[1]
        return application to url
    }

    // Checks every response against kTCS's and openTCS's OpenAPI documents.
    fun call(method: String, url: String, body: String? = null, key: String? = null): HttpResponse<String> =
        client.call(method, url, body, key)

    fun json(response: HttpResponse<String>) = Json.parseToJsonElement(response.body())

    fun destination(location: String, operation: String) = """{"locationName":"$location","operation":"$operation"}"""
    fun orderOf(vararg destinations: String) = """{"destinations":[${destinations.joinToString(",")}]}"""
    val order = orderOf(destination("Storage 01", "Load cargo"), destination("Goods out 01", "Unload cargo"))

    test("transport orders: create, read, list, duplicate, withdraw") {
        val (application, base) = start()
        try {
            val created = call("POST", "$base/transportOrders/T1", order)
            created.statusCode() shouldBe 200
            (json(created).jsonObject["name"]!!.jsonPrimitive.content) shouldBe "T1"

            call("GET", "$base/transportOrders/T1").statusCode() shouldBe 200
            (json(call("GET", "$base/transportOrders")) as JsonArray).size shouldBe 1
            call("POST", "$base/transportOrders/T1", order).let {
                it.statusCode() shouldBe 409
                it.body() shouldBe """["an object named 'T1' exists already"]"""
            }
            call("POST", "$base/transportOrders/T1/withdrawal?immediate=true").statusCode() shouldBe 200
            json(call("GET", "$base/transportOrders/T1")).jsonObject["state"]!!.jsonPrimitive.content shouldBe "FAILED"
            // The name is the path's, whatever the query says.
            json(call("POST", "$base/transportOrders/T5?NAME=Other", order)).jsonObject["name"]!!.jsonPrimitive
                .content shouldBe "T5"
            call("GET", "$base/transportOrders/Other").statusCode() shouldBe 404
        } finally {
            application.stop()
        }
    }

    test("the documented request examples (Swagger UI's Try it out) work against the demo plant") {
        val (application, base) = start()
        try {
            val paths = json(call("GET", "$base/openapi.json")).jsonObject["paths"]!!.jsonObject
            fun example(path: String, method: String) = paths[path]!!.jsonObject[method]!!.jsonObject["requestBody"]!!
                .jsonObject["content"]!!.jsonObject["application/json"]!!.jsonObject["example"]!!.toString()
            call("POST", "$base/transportOrders/TOrder-002", example("/transportOrders/{NAME}", "post"))
                .statusCode() shouldBe 200
            call("POST", "$base/orderSequences/OrderSequence-01", example("/orderSequences/{NAME}", "post"))
                .statusCode() shouldBe 200
            call("POST", "$base/plantModel/topologyUpdateRequest", example("/plantModel/topologyUpdateRequest", "post"))
                .statusCode() shouldBe 200
        } finally {
            application.stop()
        }
    }

    test("bad input is answered 400 with a message naming the problem, unknown objects 404") {
        val (application, base) = start()
        try {
            call("POST", "$base/transportOrders/T2", "{not json").let {
                it.statusCode() shouldBe 400
                it.body() shouldStartWith "[\"Malformed request body"
            }
            call("POST", "$base/transportOrders/T3", orderOf(destination("Storage 01", "Drill"))).let {
                it.statusCode() shouldBe 400
                it.body() shouldContain "operation 'Drill' is not allowed at location 'Storage 01'"
            }
            call("POST", "$base/transportOrders/T4", orderOf(destination("Nowhere", "MOVE"))).statusCode() shouldBe 404
            call("GET", "$base/transportOrders/missing").body() shouldBe """["unknown transport order 'missing'"]"""
            call("GET", "$base/vehicles?procState=SLEEPING").statusCode() shouldBe 400
            call("GET", "$base/transportOrders?intendedVehicle=Ghost").body() shouldBe """["unknown vehicle 'Ghost'"]"""
            call("GET", "$base/orderSequences?intendedVehicle=Ghost").statusCode() shouldBe 404
            call("PUT", "$base/vehicles/Vehicle-01/paused?newValue=perhaps").statusCode() shouldBe 400
            call("PUT", "$base/paths/No such path/locked?newValue=true".replace(" ", "%20")).statusCode() shouldBe 404
            call("GET", "$base/peripheralJobs").statusCode() shouldBe 404
        } finally {
            application.stop()
        }
    }

    test("vehicles, order sequences and locks") {
        val (application, base) = start()
        try {
            val vehicles = json(call("GET", "$base/vehicles")).jsonArray
            vehicles.size shouldBe 4
            call("PUT", "$base/vehicles/Vehicle-02/integrationLevel?newValue=TO_BE_RESPECTED").statusCode() shouldBe 200
            val vehicle = json(call("GET", "$base/vehicles/Vehicle-02")).jsonObject
            vehicle["integrationLevel"]!!.jsonPrimitive.content shouldBe "TO_BE_RESPECTED"
            call("GET", "$base/vehicles/Vehicle-02/commAdapter/attachmentInformation").body() shouldContain "step"
            val reroute = call("POST", "$base/vehicles/Vehicle-02/rerouteRequest?forced=true")
            reroute.statusCode() shouldBe 409
            reroute.body() shouldContain "vehicle Vehicle-02 has no transport order"

            call("POST", "$base/orderSequences/S1", """{"properties":[]}""").statusCode() shouldBe 200
            call("PUT", "$base/orderSequences/S1/complete").statusCode() shouldBe 200
            json(call("GET", "$base/orderSequences/S1")).jsonObject["complete"]!!.jsonPrimitive.content shouldBe "true"

            val path = "Point-0001 --- Point-0002"
            call("PUT", "$base/paths/${path.replace(" ", "%20")}/locked?newValue=true").statusCode() shouldBe 200
            val paths = json(call("GET", "$base/plantModel")).jsonObject["paths"]!!.jsonArray.map { it as JsonObject }
            val locked = paths.single { it["name"]!!.jsonPrimitive.content == path }["locked"]
            locked!!.jsonPrimitive.content shouldBe "true"
        } finally {
            application.stop()
        }
    }

    test("with an access key, requests without it are refused with 403") {
        val (application, base) = start("web.accessKey=secret")
        try {
            call("GET", "$base/vehicles").statusCode() shouldBe 403
            call("GET", "$base/vehicles", key = "wrong").statusCode() shouldBe 403
            call("GET", "$base/vehicles", key = "secret").statusCode() shouldBe 200
        } finally {
            application.stop()
        }
    }

    test("topology updates name existing paths; DELETE /kernel from this machine asks the application to stop") {
        val (application, base) = start("web.allowLocalShutdown=true")
        try {
            call(
                "POST",
                "$base/plantModel/topologyUpdateRequest",
                """{"paths":["Point-0001 --- Point-0002"]}""",
            ).statusCode() shouldBe
                200
            call("POST", "$base/plantModel/topologyUpdateRequest", """{"paths":["Nope"]}""").body() shouldBe
                """["unknown path 'Nope'"]"""
            call("POST", "$base/plantModel/topologyUpdateRequest", """{}""").body() shouldBe """["paths is missing"]"""

            call("DELETE", "$base/kernel").statusCode() shouldBe 200
            // The server answers first and then asks to stop, so the answer may arrive a moment before the request.
            eventually(5.seconds) { shutdownRequests.get() shouldBe 1 }
        } finally {
            application.stop()
        }
    }

    test("GET /events returns status messages by sequence number and waits for new ones up to the timeout") {
        val (application, base) = start()
        try {
            call("GET", "$base/events?timeout=20000").statusCode() shouldBe 400
            call("GET", "$base/events?minSequenceNo=abc").statusCode() shouldBe 400
            call("POST", "$base/transportOrders/T9", order).statusCode() shouldBe 200

            val first = json(call("GET", "$base/events?timeout=5000")).jsonObject["statusMessages"]!!.jsonArray
            val numbers = first.map { it.jsonObject["sequenceNumber"]!!.jsonPrimitive.content.toLong() }
            numbers shouldBe numbers.sorted()
            first.map { it.jsonObject["type"]!!.jsonPrimitive.content }.toSet() shouldContainAll setOf("TransportOrder")

            val next = numbers.last() + 1_000_000
            val started = System.nanoTime()
            json(
                call("GET", "$base/events?minSequenceNo=$next&timeout=300"),
            ).jsonObject["statusMessages"]!!.jsonArray.size shouldBe
                0
            ((System.nanoTime() - started) / 1_000_000 >= 250) shouldBe true
            // The buffer listens in the kernel context: no subscription hands every event to another thread.
            application.kernel.events.subscriberCount shouldBe 0
        } finally {
            application.stop()
        }
    }

    test("GET /sse streams the kinds of events the client asked for, named as openTCS names them") {
        val (application, base) = start()
        try {
            val request = HttpRequest.newBuilder(URI("$base/sse?/events/transportOrders=true")).build()
            val stream = http.send(request, HttpResponse.BodyHandlers.ofLines())
            stream.headers().firstValue("Content-Type").get() shouldStartWith "text/event-stream"
            call("POST", "$base/transportOrders/T10", order).statusCode() shouldBe 200
            val lines = stream.body().iterator()
            val frames = generateSequence { if (lines.hasNext()) lines.next() else null }
                .filter { it.startsWith("event: ") || it.startsWith("data: ") }
                .take(4)
                .toList()
            frames.filter { it.startsWith("event: ") } shouldBe
                listOf("event: /events/transportOrders", "event: /events/transportOrders")
            frames.filter { it.startsWith("data: ") }.forEach {
                WebApiContracts.openTcsSchemaViolations(
                    "paths/sse.yaml",
                    "/components/schemas/TransportOrderEvent",
                    it.removePrefix("data: "),
                ) shouldBe emptyList()
            }
        } finally {
            application.stop()
        }
    }

    test("browser clients from other origins are allowed as configured; oversized bodies get 413") {
        val (application, base) = start("web.allowedOrigins=https://plant.example", "web.maxRequestBodySize=1")
        try {
            fun fromPlant(method: String, path: String) = http.send(
                HttpRequest.newBuilder(URI("$base$path")).method(method, HttpRequest.BodyPublishers.noBody())
                    .header("Origin", "https://plant.example").build(),
                HttpResponse.BodyHandlers.ofString(),
            )
            val preflight = fromPlant("OPTIONS", "/transportOrders/T11")
            preflight.statusCode() shouldBe 200
            preflight.headers().firstValue("Access-Control-Allow-Origin").get() shouldBe "https://plant.example"
            fromPlant("GET", "/vehicles").headers().firstValue("Access-Control-Allow-Origin").get() shouldBe
                "https://plant.example"

            val huge = "{\"destinations\":[], \"padding\":\"" + "x".repeat(2 * 1024 * 1024) + "\"}"
            call("POST", "$base/transportOrders/T12", huge).let {
                it.statusCode() shouldBe 413
                it.body() shouldContain "larger than the limit of 1048576 bytes"
            }
        } finally {
            application.stop()
        }
    }

    test("the WebSocket sends a snapshot per topic, then every change in kernel order; bad messages get an error") {
        val (application, base) = start()
        try {
            val socket = WsTestClient(http, base)
            fun next() = socket.next()

            socket.send("""{"type":"subscribe","topics":["nonsense"]}""")
            next()["type"]!!.jsonPrimitive.content shouldBe "error"

            socket.send("""{"type":"subscribe","topics":["vehicles","transportOrders"]}""")
            val vehicles = next()
            vehicles["type"]!!.jsonPrimitive.content shouldBe "snapshot"
            vehicles["topic"]!!.jsonPrimitive.content shouldBe "vehicles"
            vehicles["objects"]!!.jsonArray.size shouldBe 4
            vehicles["v"]!!.jsonPrimitive.content shouldBe "1"
            next()["topic"]!!.jsonPrimitive.content shouldBe "transportOrders"

            call("POST", "$base/transportOrders/W1", order).statusCode() shouldBe 200
            fun JsonObject.text(key: String) = this[key]!!.jsonPrimitive.content
            val events = generateSequence { next() }.filter { it.text("topic") == "transportOrders" }.take(3).toList()
            val numbers = events.map { it.text("seq").toLong() }
            numbers shouldBe numbers.sorted()
            events.first()["previous"]!!.toString() shouldBe "null"
            events.map { it["current"]!!.jsonObject.text("state") } shouldBe listOf("RAW", "ACTIVE", "DISPATCHABLE")
            socket.close()
        } finally {
            application.stop()
        }
    }

    test("with omitUnchanged, events leave out the large fields that did not change; a wrong value gets an error") {
        val (application, base) = start()
        try {
            val socket = WsTestClient(http, base)
            val wrong = """{"type":"subscribe","topics":["transportOrders"],"omitUnchanged":"yes"}"""
            socket.shouldRefuse(wrong, "omitUnchanged")

            val subscription =
                """{"type":"subscribe","topics":["transportOrders"],"previous":false,"omitUnchanged":true}"""
            val events = socket.firstEvents(subscription) {
                call("POST", "$base/transportOrders/U1", order).statusCode() shouldBe 200
            }

            // A new order comes whole; its next state leaves out its properties, which are as before.
            events.first()["unchanged"] shouldBe null
            events.first()["current"]!!.jsonObject.keys shouldContain "properties"
            val second = events[1]
            second["unchanged"]!!.jsonArray.map { it.jsonPrimitive.content } shouldContain "properties"
            second["current"]!!.jsonObject.keys shouldNotContain "properties"

            socket.send("""{"type":"subscribe","topics":["vehicles"],"shortenedLists":true}""")
            val refused = generateSequence { socket.next() }.first { it["type"]!!.jsonPrimitive.content == "error" }
            refused["message"]!!.jsonPrimitive.content shouldContain "shortenedLists needs omitUnchanged"
            socket.send("""{"type":"subscribe","topics":["vehicles"],"omitUnchanged":true,"shortenedLists":1}""")
            val wrongType = generateSequence { socket.next() }.first { it["type"]!!.jsonPrimitive.content == "error" }
            wrongType["message"]!!.jsonPrimitive.content shouldContain "shortenedLists"
            socket.close()
        } finally {
            application.stop()
        }
    }

    test("with onlyChanged, an event of an order that was there before has its name and what changed, nothing else") {
        val (application, base) = start()
        try {
            val socket = WsTestClient(http, base)
            val wrong = """{"type":"subscribe","topics":["transportOrders"],"onlyChanged":"yes"}"""
            socket.shouldRefuse(wrong, "onlyChanged")

            val subscription =
                """{"type":"subscribe","topics":["transportOrders"],"previous":false,"onlyChanged":true}"""
            val events = socket.firstEvents(subscription) {
                call("POST", "$base/transportOrders/C1", order).statusCode() shouldBe 200
            }

            events.first()["current"]!!.jsonObject.keys shouldContain "driveOrders"
            // RAW -> ACTIVE -> DISPATCHABLE: the state, and its history entry, and nothing left out is listed.
            events.drop(1).map { it["current"]!!.jsonObject["state"]!!.jsonPrimitive.content } shouldBe
                listOf("ACTIVE", "DISPATCHABLE")
            events.drop(1).forEach {
                it["unchanged"] shouldBe null
                it["current"]!!.jsonObject.keys shouldNotContain "driveOrders"
                it["current"]!!.jsonObject.keys shouldNotContain "creationTime"
            }
            socket.close()
        } finally {
            application.stop()
        }
    }
})

/** Sends [subscription] and expects, as the next message, an error whose message names [option]. */
private fun WsTestClient.shouldRefuse(subscription: String, option: String) {
    send(subscription)
    val error = next()
    error["type"]!!.jsonPrimitive.content shouldBe "error"
    error["message"]!!.jsonPrimitive.content shouldContain option
}

/** Subscribes with [subscription], expects the snapshot, runs [change] and returns the first three events after it. */
private fun WsTestClient.firstEvents(subscription: String, change: () -> Unit): List<JsonObject> {
    send(subscription)
    next()["type"]!!.jsonPrimitive.content shouldBe "snapshot"
    change()
    return generateSequence { next() }.filter { it["type"]!!.jsonPrimitive.content == "event" }.take(3).toList()
}
