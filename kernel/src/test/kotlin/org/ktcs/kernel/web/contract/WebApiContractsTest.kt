package org.ktcs.kernel.web.contract

import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.kernel.web.contract.OpenApiContract.Violation
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.with

/** The contract checks themselves: they catch wrong bodies and undescribed answers, and accept openTCS's samples. */
class WebApiContractsTest : FunSpec({
    val json = "application/json"
    val version = """{"baselineVersion":"1.0","customizationName":"kTCS","customizationVersion":"1.0"}"""

    test("a body that keeps both contracts passes") {
        WebApiContracts.violations("GET", "/v1/kernel/version", 200, json, version).shouldBeEmpty()
    }

    test("a wrong body breaks both contracts, naming the operation, the place in the body and the problem") {
        val wrong = """{"baselineVersion":1,"customizationName":"kTCS"}"""
        val found = WebApiContracts.violations("GET", "/v1/kernel/version", 200, json, wrong)

        found.map { it.where }.toSet() shouldBe
            setOf("kTCS: GET /kernel/version -> 200", "openTCS v1: GET /kernel/version -> 200")
        found.filter { it.where.startsWith("openTCS") }.map { it.pointer }.toSet() shouldBe
            setOf("/baselineVersion", "")
        found.joinToString() shouldContain "required property 'customizationVersion' not found"
        found.first { it.pointer == "/baselineVersion" }.message shouldContain "integer found, string expected"
    }

    test("an unknown field breaks openTCS's closed schemas") {
        val extra = version.replace("}", ""","build":"x"}""")
        WebApiContracts.violations("GET", "/v1/kernel/version", 200, json, extra).joinToString() shouldContain "build"
    }

    test("an answer kTCS's document does not describe is a violation, as is a route it does not list") {
        WebApiContracts.violations("GET", "/v1/kernel/version", 418, json, "[]").map { it.toString() } shouldBe
            listOf("kTCS: GET /kernel/version -> 418 is not described")
        WebApiContracts.violations("GET", "/v1/peripheralJobs", 200, json, "[]").map { it.toString() } shouldBe
            listOf("kTCS: GET /peripheralJobs is not in kTCS's document, yet answered 200")
        WebApiContracts.violations("GET", "/v1/peripheralJobs", 404, json, """["no such resource"]""").shouldBeEmpty()
        WebApiContracts.violations("GET", "/v1/peripheralJobs", 404, json, """{"error":1}""") shouldHaveSize 1
    }

    test("a body where the operation answers none, or the wrong content type, is a violation") {
        val body = WebApiContracts.violations("PUT", "/v1/vehicles/V1/paused", 200, null, "ok")
        body shouldHaveSize 2
        body.forEach { it.message shouldContain "describes no body" }
        WebApiContracts.violations("GET", "/v1/kernel/version", 200, "text/plain", version) shouldHaveSize 2
    }

    context("openTCS's golden responses keep kTCS's document, and openTCS's specification but for its known defects") {
        withData(nameFn = { it.sample }, GOLDEN_RESPONSES) { (sample, method, path) ->
            WebApiContracts.violations(method, path, 200, json, GoldenJson.text("binding/$sample")).shouldBeEmpty()
        }
    }

    context("openTCS's golden SSE events keep kTCS's schemas, and openTCS's but for its known defects") {
        withData(GOLDEN_EVENTS.keys) { event ->
            val sample = GoldenJson.text("binding/sse/${event}TOTest.jsonSample.approved.txt")
            WebApiContracts.ktcs.violationsOf(pointer = "/components/schemas/Sse$event", json = sample).shouldBeEmpty()
            WebApiContracts.openTcsSchemaViolations("paths/sse.yaml", "/components/schemas/$event", sample)
                .shouldBeEmpty()
        }
    }

    test("every known defect of openTCS's specification is needed by a golden sample") {
        val responses = GOLDEN_RESPONSES.flatMap { (sample, method, path) ->
            val template = WebApiContracts.openTcs.template(method, path.removePrefix("/v1"))!!
            WebApiContracts.openTcs.violations(method, template, 200, json, GoldenJson.text("binding/$sample"))
        }
        val events = GOLDEN_EVENTS.keys.flatMap { event ->
            val sample = GoldenJson.text("binding/sse/${event}TOTest.jsonSample.approved.txt")
            WebApiContracts.openTcs.violationsOf(GOLDEN_EVENTS.getValue(event), "/components/schemas/$event", sample)
        }
        // No golden SSE sample has an unknown angle; this one is openTCS's vehicle event with the angle Jackson writes.
        val nanAngle = GoldenJson.element("binding/sse/VehicleEventTOTest.jsonSample.approved.txt")
            .with("currentObjectState.pose.orientationAngle", "NaN")
        val nanEvent = WebApiContracts.openTcs.violationsOf(
            SSE_FILE,
            "/components/schemas/VehicleEvent",
            nanAngle.toString(),
        )
        val excused = (responses + events + nanEvent).mapNotNull(OpenTcsSpecDefects::excusing).toSet()

        OpenTcsSpecDefects.all.filterNot { it in excused }.map { it.reason }.shouldBeEmpty()
    }

    test("a defect excuses only its own kind of violation") {
        val nullVehicle = Violation("openTCS v1", "/processingVehicle", "null found, string expected (was null)")
        OpenTcsSpecDefects.excusing(nullVehicle)!!.reason shouldContain "processingVehicle"
        OpenTcsSpecDefects.excusing(nullVehicle.copy(pointer = "/name")) shouldBe null
        OpenTcsSpecDefects.excusing(nullVehicle.copy(message = "integer found, string expected (was 1)")) shouldBe null
    }
})

private const val SSE_FILE = "fixtures/opentcs/web-api/opentcs-7.5-head/service-web-api-v1/paths/sse.yaml"

// openTCS's golden SSE event samples, by their schema name in openTCS's sse.yaml.
private val GOLDEN_EVENTS = listOf("VehicleEvent", "TransportOrderEvent", "OrderSequenceEvent").associateWith {
    SSE_FILE
}

// openTCS's golden JSON of responses, and the request that answers with it.
private data class GoldenResponse(val sample: String, val method: String, val path: String)

private val GOLDEN_RESPONSES = listOf(
    GoldenResponse("GetTransportOrderResponseTOTest.jsonSample.approved.txt", "GET", "/v1/transportOrders/T"),
    GoldenResponse("GetOrderSequenceResponseTOTest.jsonSample.approved.txt", "GET", "/v1/orderSequences/S"),
    GoldenResponse("GetVehicleResponseTOTest.jsonSample.orientationAngle-90.0.approved.txt", "GET", "/v1/vehicles/V"),
    GoldenResponse("GetVehicleResponseTOTest.jsonSample.orientationAngle-NaN.approved.txt", "GET", "/v1/vehicles/V"),
    GoldenResponse(
        "GetVehicleAttachmentInfoResponseTOTest.jsonSample.approved.txt",
        "GET",
        "/v1/vehicles/V/commAdapter/attachmentInformation",
    ),
    GoldenResponse(
        "PostVehicleRoutesResponseTOTest.jsonSample.approved.txt",
        "POST",
        "/v1/vehicles/V/routeComputationQuery",
    ),
    GoldenResponse("GetEventsResponseTOTest.jsonSample.orientationAngle-90.0.approved.txt", "GET", "/v1/events"),
    GoldenResponse("GetEventsResponseTOTest.jsonSample.orientationAngle-NaN.approved.txt", "GET", "/v1/events"),
    GoldenResponse("PlantModelTOTest.jsonSample.approved.txt", "GET", "/v1/plantModel"),
)
