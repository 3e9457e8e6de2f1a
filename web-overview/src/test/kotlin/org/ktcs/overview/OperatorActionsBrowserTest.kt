package org.ktcs.overview

import com.microsoft.playwright.Page
import com.microsoft.playwright.assertions.PlaywrightAssertions.assertThat
import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.ints.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.boolean
import kotlinx.serialization.json.int
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import kotlin.time.Duration.Companion.seconds

/**
 * The Operations Desk's operator actions in the overview, in real headless Chromium against the real application
 * (demo plant, loopback vehicles): each action is done in the page and checked in the kernel through the web API.
 */
class OperatorActionsBrowserTest : FunSpec({
    val shared = OverviewSession("() => window.ktcsOverview && window.ktcsOverview.drawn().vehicles === 4")
    val ktcs: () -> RunningKtcs = { shared.ktcs }
    val page: () -> Page = { shared.page }

    fun browserTest(name: String, body: suspend () -> Unit) = shared.test(this, name, body)

    fun json(path: String) = Json.parseToJsonElement(ktcs().get(path).body())

    fun vehicle(name: String): JsonObject = json("/v1/vehicles/$name").jsonObject

    fun orders(): List<JsonObject> = json("/v1/transportOrders").jsonArray.map { it.jsonObject }

    fun openVehicle(name: String) {
        page().locator("[data-tab=vehicles]").click()
        page().locator("[data-vehicle='$name']").click()
        assertThat(page().locator("#details h2")).hasText("Vehicle $name")
    }

    fun toast(text: String) = assertThat(page().locator("#toasts")).containsText(text)

    afterSpec { shared.close() }

    browserTest("pause all and resume all act on every vehicle and say how many") {
        page().locator("[data-action=pause-all]").click()
        toast("Paused 4 vehicles.")
        eventually(5.seconds) {
            listOf("Vehicle-01", "Vehicle-02", "Vehicle-03", "Vehicle-04").forEach {
                vehicle(it)["paused"]!!.jsonPrimitive.boolean shouldBe true
            }
        }
        page().locator("[data-action=resume-all]").click()
        toast("Resumed 4 vehicles.")
        eventually(5.seconds) { vehicle("Vehicle-03")["paused"]!!.jsonPrimitive.boolean shouldBe false }
    }

    browserTest("a vehicle is sent to a location picked in the plant, rerouted on the way, and gets there") {
        openVehicle("Vehicle-02")
        page().locator("#fit").click()
        page().locator("#details [data-action=pick-target]").click()
        val at = page().evaluate("() => window.ktcsOverview.pagePositionOf('location', 'Goods out 01')") as Map<*, *>
        page().mouse().click((at["x"] as Number).toDouble(), (at["y"] as Number).toDouble())
        assertThat(page().locator("#details [name=send-target]")).hasValue("location:Goods out 01")
        assertThat(page().locator("#details h2")).hasText("Vehicle Vehicle-02")
        assertThat(page().locator("#details [name=send-operation]")).hasValue("NOP")
        shared.watched.screenshot("operator-send-to")
        page().locator("#details [data-action=send]").click()
        toast("Send Vehicle-02 to Goods out 01: done")
        val sent = orders().single { it["name"]!!.jsonPrimitive.content.startsWith("Send-") }
        sent["intendedVehicle"]!!.jsonPrimitive.content shouldBe "Vehicle-02"
        val name = sent["name"]!!.jsonPrimitive.content
        eventually(10.seconds) { json("/v1/transportOrders/$name").toString() shouldContain "BEING_PROCESSED" }
        // Paused, the vehicle stands still with its order: a reroute has something to do.
        ktcs().put("/v1/vehicles/Vehicle-02/paused?newValue=true").statusCode() shouldBe 200
        page().locator("#details [data-action=reroute]").click()
        toast("Reroute (Vehicle-02): done")
        page().locator("#details [data-action=reroute-forced]").click()
        toast("Forced reroute (Vehicle-02): done")
        ktcs().put("/v1/vehicles/Vehicle-02/paused?newValue=false").statusCode() shouldBe 200
        eventually(60.seconds) {
            json("/v1/transportOrders/$name").jsonObject["state"]!!.jsonPrimitive.content shouldBe "FINISHED"
        }
    }

    browserTest("energy thresholds are checked before saving; order types and the driver are set") {
        openVehicle("Vehicle-03")
        val details = page().locator("#details")
        details.locator("[name=energyLevelCritical]").fill("50")
        details.locator("[name=energyLevelGood]").fill("30")
        details.locator("[data-action=save-thresholds]").click()
        toast("Energy thresholds (Vehicle-03) not saved: critical (50) must not be above good (30)")
        listOf("10", "40", "60", "90").zip(
            listOf(
                "energyLevelCritical",
                "energyLevelGood",
                "energyLevelSufficientlyRecharged",
                "energyLevelFullyRecharged",
            ),
        ).forEach { (value, field) -> details.locator("[name=$field]").fill(value) }
        details.locator("[data-action=save-thresholds]").click()
        toast("Energy thresholds (Vehicle-03): done")
        val saved = vehicle("Vehicle-03")
        saved["energyLevelCritical"]!!.jsonPrimitive.int shouldBe 10
        saved["energyLevelFullyRecharged"]!!.jsonPrimitive.int shouldBe 90

        details.locator("[name=acceptable-order-types]").fill("Transport:0, Park:2")
        details.locator("[data-action=save-order-types]").click()
        toast("Acceptable order types (Vehicle-03): done")
        vehicle("Vehicle-03")["acceptableOrderTypes"]!!.jsonArray.map {
            it.jsonObject["name"]!!.jsonPrimitive.content to it.jsonObject["priority"]!!.jsonPrimitive.int
        } shouldBe listOf("Transport" to 0, "Park" to 2)

        assertThat(details.locator("[name=driver] option[value=loopback]")).hasText("loopback (attached)")
        details.locator("[data-action=attach-driver]").click()
        toast("Attach driver loopback (Vehicle-03): done")
        details.scrollIntoViewIfNeeded()
        for (width in listOf(1920, 1440, 1024, 390)) {
            page().setViewportSize(width, if (width == 390) 844 else 1000)
            details.locator("[data-action=reroute]").scrollIntoViewIfNeeded()
            shared.watched.screenshot("operator-actions-$width")
        }
        page().setViewportSize(1440, 860)
        page().locator("#details .close").click()
    }

    browserTest("find centres the view on a vehicle; follow keeps it there until the operator pans") {
        page().locator("[name=find-vehicle]").selectOption("Vehicle-01")
        page().locator("[name=follow]").check()
        page().evaluate("() => window.ktcsOverview.following()") shouldBe "Vehicle-01"
        val canvas = page().locator("#plant-canvas").boundingBox()
        val centre = {
            page().evaluate("() => window.ktcsOverview.pagePositionOf('vehicle', 'Vehicle-01')") as Map<*, *>
        }
        eventually(5.seconds) {
            (centre()["x"] as Number).toDouble() shouldBe (canvas.x + canvas.width / 2 plusOrMinus 2.0)
            (centre()["y"] as Number).toDouble() shouldBe (canvas.y + canvas.height / 2 plusOrMinus 2.0)
        }
        val x = canvas.x + canvas.width / 4
        val y = canvas.y + canvas.height / 4
        page().mouse().move(x, y)
        page().mouse().down()
        page().mouse().move(x + 80, y + 40, com.microsoft.playwright.Mouse.MoveOptions().setSteps(5))
        page().mouse().up()
        page().evaluate("() => window.ktcsOverview.following()") shouldBe null
        assertThat(page().locator("[name=follow]")).not().isChecked()
        page().locator("#fit").click()
    }

    browserTest("vehicle labels do not cover each other when the plant is zoomed far out") {
        page().locator("#fit").click()
        repeat(8) { page().locator("#zoom-out").click() }
        page().waitForTimeout(300.0)
        val boxes = (page().evaluate("() => window.ktcsOverview.vehicleLabels()") as List<*>).map { it as Map<*, *> }
        boxes.size shouldBe 4
        fun Map<*, *>.n(key: String) = (this[key] as Number).toDouble()
        for (i in boxes.indices) {
            for (j in i + 1 until boxes.size) {
                val a = boxes[i]
                val b = boxes[j]
                val overlap = a.n("minX") < b.n("maxX") && b.n("minX") < a.n("maxX") &&
                    a.n("minY") < b.n("maxY") && b.n("minY") < a.n("maxY")
                overlap shouldBe false
            }
        }
        shared.watched.screenshot("operator-labels-zoomed-out")
        page().locator("#fit").click()
    }

    browserTest("location, point and vehicle names do not cover each other, zoomed in or far out") {
        fun Map<*, *>.n(key: String) = (this[key] as Number).toDouble()
        fun drawnNames(): List<Map<*, *>> {
            page().waitForTimeout(200.0)
            return (page().evaluate("() => window.ktcsOverview.plantLabels()") as List<*>).map { it as Map<*, *> }
        }
        fun List<Map<*, *>>.overlapping() = indices.flatMap { i ->
            (i + 1 until size).filter { j ->
                val a = this[i]
                val b = this[j]
                a.n(
                    "minX",
                ) < b.n("maxX") && b.n("minX") < a.n("maxX") && a.n("minY") < b.n("maxY") && b.n("minY") < a.n("maxY")
            }
        }
        page().locator("#fit").click()
        val fitted = drawnNames()
        fitted.size shouldBeGreaterThanOrEqual 16
        fitted.overlapping() shouldBe emptyList()
        val vehicleNames = (page().evaluate("() => window.ktcsOverview.vehicleLabels()") as List<*>).map {
            it as Map<*, *>
        }
        vehicleNames.size shouldBe 4
        (fitted + vehicleNames).overlapping() shouldBe emptyList()
        repeat(6) { page().locator("#zoom-out").click() }
        val far = drawnNames()
        far.size shouldBeGreaterThanOrEqual 1
        far.size shouldBeLessThan fitted.size
        far.overlapping() shouldBe emptyList()
        shared.watched.screenshot("operator-plant-names-zoomed-out")
        page().locator("#fit").click()
    }

    browserTest("the create-order dialog takes properties per destination and refuses a property without key") {
        page().locator("[data-tab=orders]").click()
        page().locator("[data-action=new-order]").click()
        val dialog = page().locator("#order-dialog")
        dialog.locator("[name=destination]").first().selectOption("location:Storage 01")
        dialog.locator("[name=operation]").first().selectOption("Load cargo")
        dialog.locator("[data-action=add-property]").first().click()
        dialog.locator("[name=property-value]").first().fill("slow")
        dialog.locator("[name=name]").fill("With-Properties")
        dialog.locator("[data-action=create-order]").click()
        assertThat(dialog.locator(".form-error")).hasText("Destination 1: the property with value 'slow' needs a key.")
        dialog.locator("[name=property-key]").first().fill("speed")
        shared.watched.screenshot("operator-destination-properties")
        dialog.locator("[data-action=create-order]").click()
        toast("Created transport order With-Properties")
        val order = json("/v1/transportOrders/With-Properties").jsonObject
        val properties = order["destinations"]!!.jsonArray.single().jsonObject["properties"]!!.jsonArray
            .map { it.jsonObject["key"]!!.jsonPrimitive.content to it.jsonObject["value"]!!.jsonPrimitive.content }
        properties shouldContain ("speed" to "slow")
    }

    browserTest("the order details show its history; the sequences view lists sequences with their orders") {
        ktcs().post("/v1/orderSequences/Seq-1", """{"failureFatal":true,"properties":[]}""").statusCode() shouldBe 200
        ktcs().post(
            "/v1/transportOrders/In-Seq-1",
            """{"wrappingSequence":"Seq-1","destinations":[{"locationName":"Storage 01","operation":"Load cargo"}]}""",
        ).statusCode() shouldBe 200
        page().locator("[data-tab=sequences]").click()
        val row = page().locator("[data-sequence='Seq-1']")
        assertThat(row).containsText("open for more")
        row.click()
        assertThat(page().locator("#details h2")).hasText("Order sequence Seq-1")
        assertThat(page().locator("#details")).containsText("Failure fatal")
        assertThat(page().locator("#details .sequence-orders")).containsText("In-Seq-1")
        shared.watched.screenshot("operator-sequence")
        page().locator("#details .sequence-orders [data-order='In-Seq-1']").click()
        assertThat(page().locator("#details h2")).hasText("Order In-Seq-1")
        val history = page().locator("#details [data-view=history]")
        assertThat(history).containsText("created")
        page().evaluate("() => { const d = document.getElementById('details'); d.scrollTop = d.scrollHeight; }")
        shared.watched.screenshot("operator-order-history")
        ktcs().put("/v1/orderSequences/Seq-1/complete").statusCode() shouldBe 200
        page().locator("[data-tab=sequences]").click()
        eventually(60.seconds) {
            json("/v1/orderSequences/Seq-1").jsonObject["finished"]!!.jsonPrimitive.boolean shouldBe true
        }
        assertThat(row).containsText("finished")
        page().locator("#details .close").click()
    }
})
