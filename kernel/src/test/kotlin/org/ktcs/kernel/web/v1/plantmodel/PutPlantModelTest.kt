package org.ktcs.kernel.web.v1.plantmodel

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldBeIn
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
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
import org.ktcs.kernel.persistence.PlantModelFiles
import org.ktcs.kernel.persistence.PublishedModelFile
import org.ktcs.kernel.web.WebApiClient
import org.ktcs.kernel.web.WsTestClient
import java.net.http.HttpClient
import java.net.http.HttpResponse
import kotlin.time.Duration.Companion.seconds

/** `PUT /v1/plantModel` on a running kernel: replacing the plant, and every reason to refuse it. */
class PutPlantModelTest : FunSpec({
    val testVehicles = object : KtcsExtension {
        override val name = "step-vehicles"

        override fun module(): Module = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
    }
    val http = HttpClient.newHttpClient()
    lateinit var application: KernelApplication
    lateinit var base: String
    lateinit var data: java.io.File

    beforeEach {
        data = tempdir()
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf(
                "web.bindAddress=127.0.0.1",
                "web.port=0",
                "dispatcher.parkIdleVehicles=false",
                "kernel.dataDirectory=$data",
            ),
        )
        application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(testVehicles))
        base = Regex("web API (http://\\S+/v1)").find(application.start())!!.groupValues[1]
    }
    afterEach { application.stop() }

    val client = WebApiClient(http)

    fun call(method: String, path: String, body: String? = null): HttpResponse<String> =
        client.call(method, base + path, body)

    fun model(): JsonObject = Json.parseToJsonElement(call("GET", "/plantModel").body()).jsonObject
    fun JsonObject.names(field: String) = this[field]!!.jsonArray.map { it.jsonObject["name"]!!.jsonPrimitive.content }
    fun JsonObject.with(field: String, value: kotlinx.serialization.json.JsonElement) =
        JsonObject(this + (field to value))

    // The demo plant, renamed and without its last vehicle.
    fun changedModel(): JsonObject {
        val current = model()
        val vehicles = JsonArray(current["vehicles"]!!.jsonArray.dropLast(1))
        return current.with("name", JsonPrimitive("Hall 2")).with("vehicles", vehicles)
    }

    val order = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"},""" +
        """{"locationName":"Goods out 01","operation":"Unload cargo"}]}"""

    test("replaces the plant: the new model and its vehicles are served, final orders are gone, orders run again") {
        call("POST", "/transportOrders/Before", order).statusCode() shouldBe 200
        call("POST", "/transportOrders/Before/withdrawal?immediate=true").statusCode() shouldBe 200

        // The withdrawn order is final at once, but its vehicle finishes the movement it was on before kTCS agrees.
        val changed = changedModel().toString()
        eventually(20.seconds) {
            val answer = call("PUT", "/plantModel", changed)
            withClue(answer.body()) { answer.statusCode() shouldBe 200 }
        }

        val replaced = model()
        replaced["name"]!!.jsonPrimitive.content shouldBe "Hall 2"
        replaced.names("vehicles") shouldContainExactly listOf("Vehicle-01", "Vehicle-02", "Vehicle-03")
        call("GET", "/vehicles/Vehicle-04").statusCode() shouldBe 404
        call("GET", "/transportOrders/Before").statusCode() shouldBe 404
        call("POST", "/transportOrders/After", order).statusCode() shouldBe 200
        eventually(10.seconds) {
            val after = Json.parseToJsonElement(call("GET", "/transportOrders/After").body()).jsonObject
            after["processingVehicle"]!!.jsonPrimitive.content shouldBeIn
                listOf("Vehicle-01", "Vehicle-02", "Vehicle-03")
        }
    }

    test("is refused with 409 naming the orders while an order is not final, and the plant stays as it was") {
        call("PUT", "/vehicles/Vehicle-01/paused?newValue=true")
        val forPausedVehicle = order.replace("{\"destinations", "{\"intendedVehicle\":\"Vehicle-01\",\"destinations")
        call("POST", "/transportOrders/Busy", forPausedVehicle).statusCode() shouldBe 200

        val refused = call("PUT", "/plantModel", changedModel().toString())

        refused.statusCode() shouldBe 409
        refused.body() shouldContain "while orders are being processed: 1 transport order(s) not final (Busy)"
        model()["name"]!!.jsonPrimitive.content shouldBe "kTCS Demo"
        model().names("vehicles").size shouldBe 4
    }

    test("is refused with 400 naming the problems of an invalid model, and the plant stays as it was") {
        val path = JsonObject(
            mapOf(
                "name" to JsonPrimitive("Nowhere"),
                "srcPointName" to JsonPrimitive("Point-0001"),
                "destPointName" to JsonPrimitive("Point-9999"),
            ),
        )
        val invalid = changedModel().let { it.with("paths", JsonArray(it["paths"]!!.jsonArray + path)) }

        val refused = call("PUT", "/plantModel", invalid.toString())

        refused.statusCode() shouldBe 400
        refused.body() shouldContain "Point-9999"
        model()["name"]!!.jsonPrimitive.content shouldBe "kTCS Demo"
    }

    test("malformed JSON, a missing name and impossible values are 400 with the reason") {
        call("PUT", "/plantModel", "{\"name\":").statusCode() shouldBe 400
        call("PUT", "/plantModel", "{\"points\":[]}").let {
            it.statusCode() shouldBe 400
            it.body() shouldContain "name"
        }
        val negative = changedModel().let { current ->
            val paths = current["paths"]!!.jsonArray
            val first = paths.first().jsonObject.with("length", JsonPrimitive(-5))
            current.with("paths", JsonArray(listOf(first) + paths.drop(1)))
        }
        call("PUT", "/plantModel", negative.toString()).let {
            it.statusCode() shouldBe 400
            it.body() shouldContain "length"
        }
    }

    test("WebSocket clients are told the model was replaced and get fresh snapshots") {
        val socket = WsTestClient(http, base)
        fun next() = socket.next()
        fun JsonObject.text(key: String) = this[key]!!.jsonPrimitive.content
        socket.send("""{"type":"subscribe","topics":["vehicles"]}""")
        next()["objects"]!!.jsonArray.size shouldBe 4

        call("PUT", "/plantModel", changedModel().toString()).statusCode() shouldBe 200

        val replaced = generateSequence { next() }.first { it.text("type") == "modelReplaced" }
        replaced.text("name") shouldBe "Hall 2"
        val snapshot = next()
        snapshot.text("type") shouldBe "snapshot"
        snapshot["objects"]!!.jsonArray.map { it.jsonObject.text("name") } shouldContainExactly
            listOf("Vehicle-01", "Vehicle-02", "Vehicle-03")
        socket.close()
    }

    test("a replaced plant is saved to the data directory, the one before kept as backup; the next start runs it") {
        val published = PublishedModelFile(data.toPath())
        published.exists() shouldBe false

        call("PUT", "/plantModel", changedModel().toString()).statusCode() shouldBe 200
        PlantModelFiles.read(published.file).name shouldBe "Hall 2"
        call(
            "PUT",
            "/plantModel",
            changedModel().with("name", JsonPrimitive("Hall 3")).toString(),
        ).statusCode() shouldBe 200

        PlantModelFiles.read(published.file).name shouldBe "Hall 3"
        PlantModelFiles.read(published.backup).name shouldBe "Hall 2"
        val restarted = PlantModelLoader.loadAtStart(null, published)
        restarted.model.name shouldBe "Hall 3"
        restarted.model.vehicles.size shouldBe 2 // each changed model drops the last vehicle
        restarted.source shouldContain "published model"
        // --model still wins over the published model.
        val demo = data.resolve("demo.xml").toPath()
        PlantModelFiles.write(PlantModelLoader.loadDemo().model, demo)
        PlantModelLoader.loadAtStart(demo, published).model.name shouldBe "kTCS Demo"
    }

    test("an invalid model is not saved: the published file stays as it was") {
        call("PUT", "/plantModel", changedModel().toString()).statusCode() shouldBe 200
        val before = java.nio.file.Files.readString(PublishedModelFile(data.toPath()).file)
        val invalid = changedModel().with("name", JsonPrimitive("Broken")).let {
            val path = it["paths"]!!.jsonArray.first().jsonObject.with("destPointName", JsonPrimitive("Point-9999"))
            it.with("paths", JsonArray(listOf(path) + it["paths"]!!.jsonArray.drop(1)))
        }

        call("PUT", "/plantModel", invalid.toString()).statusCode() shouldBe 400

        java.nio.file.Files.readString(PublishedModelFile(data.toPath()).file) shouldBe before
    }

    test("locks and velocities change while an order runs: no vehicle restarts, the order stays, the file has them") {
        call("PUT", "/vehicles/Vehicle-01/paused?newValue=true")
        val forPausedVehicle = order.replace("{\"destinations", "{\"intendedVehicle\":\"Vehicle-01\",\"destinations")
        call("POST", "/transportOrders/Busy", forPausedVehicle).statusCode() shouldBe 200
        val current = model()
        val paths = current["paths"]!!.jsonArray
        val first = paths.first().jsonObject.with("locked", JsonPrimitive(true)).with("maxVelocity", JsonPrimitive(321))
        val changed = current.with("paths", JsonArray(listOf(first) + paths.drop(1)))

        val answer = call("PUT", "/plantModel", changed.toString())

        withClue(answer.body()) { answer.statusCode() shouldBe 200 }
        val name = first["name"]!!.jsonPrimitive.content
        val served = model()["paths"]!!.jsonArray.map {
            it.jsonObject
        }.first { it["name"]!!.jsonPrimitive.content == name }
        served["locked"]!!.jsonPrimitive.content shouldBe "true"
        served["maxVelocity"]!!.jsonPrimitive.content shouldBe "321"
        call("GET", "/transportOrders/Busy").statusCode() shouldBe 200
        call("GET", "/vehicles/Vehicle-01").body() shouldContain "\"paused\":true"
        PlantModelFiles.read(PublishedModelFile(data.toPath()).file).path(name)!!.maxVelocity shouldBe 321
    }
})
