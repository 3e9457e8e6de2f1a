package org.ktcs.kernel.web.v1.plantmodel

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.boolean
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.reliability.send
import org.ktcs.kernel.reliability.startKernel
import org.ktcs.kernel.web.WebApiClient

/** The reader, writer and validator the overview's modelling mode uses, on a running kernel. */
class PlantModelFileRoutesTest : FunSpec({
    val (application, base) = startKernel()
    afterSpec { application.stop() }
    val client = WebApiClient()
    val demoFile = PlantModelLoader::class.java.getResourceAsStream(PlantModelLoader.DEMO_RESOURCE)!!
        .use { String(it.readAllBytes(), Charsets.UTF_8) }

    fun call(method: String, path: String, body: String? = null) = client.call(method, base + path, body)
    fun JsonObject.array(field: String) = this[field]!!.jsonArray

    test("a file read into JSON and written back is byte for byte the file openTCS's layout gives (the demo plant)") {
        val read = call("POST", "/plantModel/fromFile", demoFile)
        read.statusCode() shouldBe 200
        val answer = Json.parseToJsonElement(read.body()).jsonObject
        val model = answer["model"]!!.jsonObject
        model["name"]!!.jsonPrimitive.content shouldBe "kTCS Demo"
        model.array("points").size shouldBe 59

        val written = call("POST", "/plantModel/toFile", model.toString())

        written.statusCode() shouldBe 200
        written.headers().firstValue("Content-Type").get() shouldContain "application/xml"
        written.body() shouldBe demoFile
    }

    test("a file that is no plant model, or no body at all, is 400 with the reader's reason") {
        call("POST", "/plantModel/fromFile", "<model version=\"9.9.9\" name=\"x\"/>").let {
            it.statusCode() shouldBe 400
            it.body() shouldContain "9.9.9"
        }
        call("POST", "/plantModel/fromFile", "not xml").statusCode() shouldBe 400
        call("POST", "/plantModel/fromFile", "").let {
            it.statusCode() shouldBe 400
            it.body() shouldContain "empty"
        }
        call("POST", "/plantModel/toFile", "{\"points\":[]}").let {
            it.statusCode() shouldBe 400
            it.body() shouldContain "name"
        }
    }

    test("validation names the element of each problem; a valid model says so") {
        val model = Json.parseToJsonElement(call("GET", "/plantModel").body()).jsonObject
        Json.parseToJsonElement(call("POST", "/plantModel/validation", model.toString()).body())
            .jsonObject["valid"]!!.jsonPrimitive.boolean shouldBe true
        val dangling = JsonObject(
            mapOf(
                "name" to JsonPrimitive("Nowhere"),
                "srcPointName" to JsonPrimitive("Point-0001"),
                "destPointName" to JsonPrimitive("Point-9999"),
            ),
        )
        val invalid = JsonObject(model + ("paths" to JsonArray(model.array("paths") + dangling)))

        val answer = call("POST", "/plantModel/validation", invalid.toString())

        answer.statusCode() shouldBe 200
        val validation = Json.parseToJsonElement(answer.body()).jsonObject
        validation["valid"]!!.jsonPrimitive.boolean shouldBe false
        val problem = validation.array("problems").map {
            it.jsonObject
        }.first { it["severity"]!!.jsonPrimitive.content == "ERROR" }
        problem["element"]!!.jsonPrimitive.content shouldBe "path 'Nowhere'"
        problem["name"]!!.jsonPrimitive.content shouldBe "Nowhere"
        problem["message"]!!.jsonPrimitive.content shouldContain "Point-9999"
    }

    test("a file sent as application/xml, as the overview sends it, is read; a text/plain body is refused") {
        val http = java.net.http.HttpClient.newHttpClient()
        val headers = mapOf("Content-Type" to "application/xml", "X-Requested-With" to "test")
        send(http, "POST", "$base/plantModel/fromFile", demoFile, headers = headers).statusCode() shouldBe 200
        send(http, "POST", "$base/plantModel/fromFile", demoFile, headers = mapOf("Content-Type" to "text/plain"))
            .statusCode() shouldBe 415
    }
})
