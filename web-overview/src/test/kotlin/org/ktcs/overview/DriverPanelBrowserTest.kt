package org.ktcs.overview

import com.microsoft.playwright.Locator
import com.microsoft.playwright.Page
import com.microsoft.playwright.assertions.LocatorAssertions
import com.microsoft.playwright.assertions.PlaywrightAssertions.assertThat
import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import kotlin.time.Duration.Companion.seconds

/**
 * The loopback driver's panel in a vehicle's details, in real headless Chromium against the real application:
 * placing a vehicle by dragging it onto a point, energy and state, single-step mode. One application and one page
 * serve every test, in order; every test fails on any console or page error.
 */
class DriverPanelBrowserTest : FunSpec({
    val overview = OverviewSession()
    val page: () -> Page = { overview.page }

    fun browserTest(name: String, body: suspend () -> Unit) = overview.test(this, name, body)

    fun vehicle(name: String): JsonObject = Json.parseToJsonElement(
        overview.ktcs.get("/v1/vehicles/$name").body(),
    ).jsonObject

    fun orderState(name: String): String =
        Json.parseToJsonElement(
            overview.ktcs.get("/v1/transportOrders/$name").body(),
        ).jsonObject["state"]!!.jsonPrimitive.content

    fun finishedCommands(vehicle: String, order: String): Int =
        Json.parseToJsonElement(overview.ktcs.get("/v1/vehicles/$vehicle/driverEvents").body()).jsonArray
            .map { it.jsonObject }
            .count {
                it["type"]!!.jsonPrimitive.content == "loopback:commandFinished" &&
                    it["payload"]!!.jsonObject["order"]!!.jsonPrimitive.content == order
            }

    fun pagePosition(kind: String, name: String): Pair<Double, Double> {
        val found = page().evaluate("([k, n]) => window.ktcsOverview.pagePositionOf(k, n)", listOf(kind, name))
            as Map<*, *>
        return (found["x"] as Number).toDouble() to (found["y"] as Number).toDouble()
    }

    fun select(vehicle: String): Locator {
        page().locator("[data-tab=vehicles]").click()
        page().locator("[data-vehicle='$vehicle']").click()
        assertThat(page().locator("#details h2")).hasText("Vehicle $vehicle")
        val panel = page().locator("#details [data-role=loopback]")
        assertThat(panel).isVisible()
        return panel
    }

    fun fact(label: String): Locator = page().locator("#details .details-info tr:has(th:text-is('$label')) td")

    fun postOrder(name: String, vehicle: String) = overview.ktcs.post(
        "/v1/transportOrders/$name",
        """{"intendedVehicle":"$vehicle","destinations":[{"locationName":"Storage 01","operation":"Load cargo"},
           {"locationName":"Goods out 01","operation":"Unload cargo"}]}""",
    ).statusCode() shouldBe 200

    afterSpec {
        overview.close()
    }

    browserTest("a vehicle dragged onto a point is placed there, then runs an order to FINISHED") {
        val target = "Point-0020"
        select("Vehicle-01")
        page().locator("#fit").click()
        page().waitForFunction("() => window.ktcsOverview.pagePositionOf('vehicle', 'Vehicle-01') !== null")
        val (fromX, fromY) = pagePosition("vehicle", "Vehicle-01")
        val (toX, toY) = pagePosition("point", target)
        page().mouse().move(fromX, fromY)
        page().mouse().down()
        page().mouse().move(toX, toY, com.microsoft.playwright.Mouse.MoveOptions().setSteps(12))
        overview.watched.screenshot("driver-panel-dragging")
        page().mouse().up()
        assertThat(page().locator("#toasts")).containsText("Place on $target (Vehicle-01): done")
        eventually(10.seconds) { vehicle("Vehicle-01")["currentPosition"]!!.jsonPrimitive.content shouldBe target }
        assertThat(fact("Position")).hasText(target)

        postOrder("Dragged-1", "Vehicle-01")
        val queue = page().locator("#details [data-role=command-queue] tbody")
        assertThat(queue).containsText("Point-", LocatorAssertions.ContainsTextOptions().setTimeout(10_000.0))
        eventually(30.seconds) { orderState("Dragged-1") shouldBe "FINISHED" }
        assertThat(page().locator("#details [data-role=driver-events]")).containsText("commandFinished")
        assertThat(queue).hasText("no commands", LocatorAssertions.HasTextOptions().setTimeout(10_000.0))
    }

    browserTest("energy and state set in the panel show in the vehicle's details") {
        // A vehicle that charges sets its own state when it is done: start from one that rests.
        val full = """{"driver":"loopback","command":"tcs:virtualVehicle:setEnergyLevel",""" +
            """"parameters":{"value":"100"}}"""
        overview.ktcs.post("/v1/vehicles/Vehicle-04/driverCommand", full).statusCode() shouldBe 200
        eventually(30.seconds) {
            val resting = vehicle("Vehicle-04")
            resting["state"]!!.jsonPrimitive.content to resting["procState"]!!.jsonPrimitive.content shouldBe
                ("IDLE" to "IDLE")
        }
        val panel = select("Vehicle-04")
        panel.locator("[data-field=state]").selectOption("ERROR")
        panel.locator("[data-action=set-state]").click()
        assertThat(fact("State")).hasText("ERROR")
        panel.locator("[data-field=energy]").fill("37")
        panel.locator("[data-action=set-energy]").click()
        assertThat(fact("Energy")).hasText("37%")
        for (width in listOf(1920, 1440, 1024, 390)) {
            page().setViewportSize(width, if (width == 390) 844 else 900)
            panel.scrollIntoViewIfNeeded()
            overview.watched.screenshot("driver-panel-$width")
        }
        page().setViewportSize(1440, 860)
        // A bad value is refused by the kernel with a message that names it; nothing changes.
        panel.locator("[data-field=energy]").fill("140")
        panel.locator("[data-action=set-energy]").click()
        assertThat(page().locator("#toasts")).containsText("must be a whole number from 0 to 100, was '140'")
        // The browser logs the refused request as a console error; that one is expected.
        overview.watched.errors.removeIf { it.contains("status of 400") }
        assertThat(fact("Energy")).hasText("37%")
        vehicle("Vehicle-04")["energyLevel"]!!.jsonPrimitive.content.toInt() shouldBe 37
        panel.locator("[data-field=state]").selectOption("IDLE")
        panel.locator("[data-action=set-state]").click()
        assertThat(fact("State")).hasText("IDLE")
    }

    browserTest("in single-step mode each click on Step carries out one command") {
        val panel = select("Vehicle-02")
        panel.locator("[data-field=single-step]").check()
        assertThat(page().locator("#toasts")).containsText("Single-step mode (Vehicle-02): done")
        postOrder("Stepped-1", "Vehicle-02")
        val step = panel.locator("[data-action=step]")
        for (clicks in 1..2) {
            assertThat(step).isEnabled(LocatorAssertions.IsEnabledOptions().setTimeout(10_000.0))
            finishedCommands("Vehicle-02", "Stepped-1") shouldBe clicks - 1
            step.click()
            eventually(15.seconds) { finishedCommands("Vehicle-02", "Stepped-1") shouldBe clicks }
        }
        // Without another click the vehicle waits for its next step.
        assertThat(step).isEnabled(LocatorAssertions.IsEnabledOptions().setTimeout(10_000.0))
        Thread.sleep(1_500)
        finishedCommands("Vehicle-02", "Stepped-1") shouldBe 2
        orderState("Stepped-1") shouldBe "BEING_PROCESSED"
        // For the README: the panel without the action messages over the plant.
        page().evaluate("() => document.getElementById('toasts').style.visibility = 'hidden'")
        overview.watched.screenshot("driver-panel-single-step")
        page().evaluate("() => document.getElementById('toasts').style.visibility = ''")
        panel.locator("[data-field=single-step]").uncheck()
        eventually(30.seconds) { orderState("Stepped-1") shouldBe "FINISHED" }
        page().locator("#details .close").click()
    }
})
