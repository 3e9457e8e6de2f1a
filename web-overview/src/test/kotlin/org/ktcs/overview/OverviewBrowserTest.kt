package org.ktcs.overview

import com.microsoft.playwright.Locator
import com.microsoft.playwright.Page
import com.microsoft.playwright.assertions.LocatorAssertions
import com.microsoft.playwright.assertions.PlaywrightAssertions.assertThat
import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldBeIn
import io.kotest.matchers.collections.shouldNotBeEmpty
import io.kotest.matchers.doubles.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.boolean
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import kotlinx.serialization.json.long
import java.net.URLEncoder
import java.util.regex.Pattern
import kotlin.math.hypot
import kotlin.time.Duration.Companion.seconds

private val FINAL_STATES = setOf("FINISHED", "FAILED", "UNROUTABLE", "WITHDRAWN")
private val CREATED = Regex("created (\\d+)")

private fun encode(name: String): String = URLEncoder.encode(name, Charsets.UTF_8).replace("+", "%20")

/**
 * The overview in real headless Chromium against the real application (demo plant, loopback vehicles). One
 * application and one page serve every test, in order; every test fails on any console or page error.
 */
class OverviewBrowserTest : FunSpec({
    val overview = OverviewSession()
    val page: () -> Page = { overview.page }

    fun browserTest(name: String, body: suspend () -> Unit) = overview.test(this, name, body)

    fun model(): JsonObject = Json.parseToJsonElement(overview.ktcs.get("/v1/plantModel").body()).jsonObject

    fun drawn(): Map<*, *> = page().evaluate("() => window.ktcsOverview.drawn()") as Map<*, *>

    fun position(kind: String, name: String): Pair<Double, Double>? {
        val found = page().evaluate("([k, n]) => window.ktcsOverview.pagePositionOf(k, n)", listOf(kind, name))
            as Map<*, *>? ?: return null
        return (found["x"] as Number).toDouble() to (found["y"] as Number).toDouble()
    }

    fun longestPath(): String = model()["paths"]!!.jsonArray.map { it.jsonObject }
        .maxBy { it["length"]!!.jsonPrimitive.long }["name"]!!.jsonPrimitive.content

    fun drawnNames(what: String): List<String> =
        (page().evaluate("() => window.ktcsOverview.$what()") as List<*>).map { it as String }

    /** Every resource a vehicle holds (allocated or claimed), as the kernel tells it. */
    fun heldByVehicles(): List<String> = Json.parseToJsonElement(overview.ktcs.get("/v1/vehicles").body()).jsonArray
        .flatMap { vehicle ->
            listOf("allocatedResources", "claimedResources").flatMap { key ->
                vehicle.jsonObject[key]!!.jsonArray.flatMap { set -> set.jsonArray.map { it.jsonPrimitive.content } }
            }
        }.distinct().sorted()

    suspend fun withdrawOpenOrders() {
        val open = {
            Json.parseToJsonElement(overview.ktcs.get("/v1/transportOrders").body()).jsonArray.map { it.jsonObject }
                .filter { it["state"]!!.jsonPrimitive.content !in FINAL_STATES }
                .map { it["name"]!!.jsonPrimitive.content }
        }
        open().forEach { overview.ktcs.post("/v1/transportOrders/${encode(it)}/withdrawal?immediate=true", "") }
        eventually(20.seconds) { open().shouldBeEmpty() }
    }

    afterSpec {
        overview.close()
    }

    browserTest("the plant shows as many points, paths and locations as the model has; layers hide them") {
        val model = model()
        page().waitForFunction("() => window.ktcsOverview.drawn().vehicles > 0")
        val counts = drawn()
        (counts["points"] as Number).toInt() shouldBe model["points"]!!.jsonArray.size
        (counts["paths"] as Number).toInt() shouldBe model["paths"]!!.jsonArray.size
        (counts["locations"] as Number).toInt() shouldBe model["locations"]!!.jsonArray.size
        assertThat(page().locator("#plant-summary")).containsText("${model["points"]!!.jsonArray.size} points")
        assertThat(page().locator("#connection")).hasText("live")
        (page().evaluate("() => window.ktcsOverview.vehicleStyle('Vehicle-01')") as Map<*, *>)["label"] shouldBe
            "Vehicle-01"
        overview.watched.screenshot("plant")
        page().locator("[data-layer='0']").uncheck()
        page().waitForFunction("() => window.ktcsOverview.drawn().points === 0")
        page().locator("[data-layer='0']").check()
        page().waitForFunction("n => window.ktcsOverview.drawn().points === n", model["points"]!!.jsonArray.size)
    }

    browserTest("a vehicle's drawn position changes while it drives") {
        val created = overview.ktcs.post(
            "/v1/transportOrders/Drive-1",
            """{"intendedVehicle":"Vehicle-01","destinations":[{"locationName":"Storage 01","operation":"Load cargo"},
               {"locationName":"Goods out 01","operation":"Unload cargo"}]}""",
        )
        created.statusCode() shouldBe 200
        page().waitForFunction("() => window.ktcsOverview.pagePositionOf('vehicle', 'Vehicle-01') !== null")
        val start = position("vehicle", "Vehicle-01")!!
        page().waitForFunction(
            "([x, y]) => { const p = window.ktcsOverview.pagePositionOf('vehicle', 'Vehicle-01');" +
                " return Math.hypot(p.x - x, p.y - y) > 5; }",
            listOf(start.first, start.second),
            Page.WaitForFunctionOptions().setTimeout(20_000.0),
        )
        val later = position("vehicle", "Vehicle-01")!!
        hypot(later.first - start.first, later.second - start.second) shouldBeGreaterThan 5.0
        page().locator("[data-vehicle='Vehicle-01']").click()
        assertThat(page().locator("#details h2")).hasText("Vehicle Vehicle-01")
        // Its properties as a table under their heading, not the elements' names as text.
        assertThat(
            page().locator("#details table.props th").filter(
                Locator.FilterOptions().setHasText("loopback:initialPosition"),
            ),
        ).hasCount(1)
        assertThat(page().locator("#details")).not().containsText("[object")
        overview.watched.screenshot("vehicle-details")
    }

    browserTest("an order created in the dialog reaches FINISHED in the order table") {
        page().locator("[data-tab=orders]").click()
        page().locator("[data-action=new-order]").click()
        val dialog = page().locator("#order-dialog")
        dialog.locator("[name=destination]").selectOption("location:Storage 01")
        dialog.locator("[name=operation]").selectOption("Load cargo")
        dialog.getByText("+ Destination").click()
        dialog.locator("[name=destination]").nth(1).selectOption("location:Goods out 01")
        dialog.locator("[name=operation]").nth(1).selectOption("Unload cargo")
        dialog.locator("[name=name]").fill("Browser-Order-1")
        overview.watched.screenshot("order-dialog")
        dialog.locator("[data-action=create-order]").click()
        val state = page().locator("[data-order='Browser-Order-1'] [data-column=state]")
        assertThat(state).hasText("FINISHED", LocatorAssertions.HasTextOptions().setTimeout(60_000.0))
        page().locator("[data-order='Browser-Order-1']").click()
        assertThat(page().locator("#details h2")).hasText("Order Browser-Order-1")
        overview.watched.screenshot("orders")
    }

    browserTest("a path locked in the page is locked in the kernel") {
        val path = model()["paths"]!!.jsonArray.map { it.jsonObject }.maxBy { it["length"]!!.jsonPrimitive.long }
        val name = path["name"]!!.jsonPrimitive.content
        page().locator("#fit").click()
        val (x, y) = position("path", name)!!
        page().mouse().click(x, y)
        assertThat(page().locator("#details h2")).hasText("Path $name")
        page().locator("#details [data-action=lock]").click()
        assertThat(page().locator("#toasts")).containsText("Lock path $name: done")
        val locked = { model()["paths"]!!.jsonArray.first { it.jsonObject["name"]!!.jsonPrimitive.content == name } }
        locked().jsonObject["locked"]!!.jsonPrimitive.boolean shouldBe true
        overview.watched.screenshot("path-locked")
        page().locator("#details [data-action=unlock]").click()
        assertThat(page().locator("#toasts")).containsText("Unlock path $name: done")
        locked().jsonObject["locked"]!!.jsonPrimitive.boolean shouldBe false
        page().locator("#details .close").click()
    }

    browserTest(
        "a loopback vehicle left loaded says why it refuses a load; its load reset in the details lets it work",
    ) {
        val vehicle = "Vehicle-03"
        val loaded = """{"type":"tcs:virtualVehicle:setLoaded","parameters":[{"key":"value","value":"true"}]}"""
        overview.ktcs.post("/v1/vehicles/$vehicle/commAdapter/message", loaded).statusCode() shouldBe 200
        overview.ktcs.post(
            "/v1/transportOrders/Loaded-1",
            """{"intendedVehicle":"$vehicle","destinations":[{"locationName":"Storage 01","operation":"Load cargo"},
               {"locationName":"Goods out 01","operation":"Unload cargo"}]}""",
        ).statusCode() shouldBe 200
        page().locator("[data-tab=vehicles]").click()
        page().locator("[data-vehicle='$vehicle']").click()
        assertThat(page().locator("#details h2")).hasText("Vehicle $vehicle")
        val reason = page().locator("#details tr")
            .filter(Locator.FilterOptions().setHasText("Takes no orders because")).locator("td")
        assertThat(reason).containsText("driver refused: cannotLoadWhenLoaded")
        val loopback = page().locator("#details [data-role=loopback]")
        assertThat(loopback.locator("[data-role=load-state]")).hasText("carries a load")
        val orderState = {
            Json.parseToJsonElement(overview.ktcs.get("/v1/transportOrders/Loaded-1").body()).jsonObject["state"]!!
                .jsonPrimitive.content
        }
        orderState() shouldBe "DISPATCHABLE"
        loopback.scrollIntoViewIfNeeded()
        overview.watched.screenshot("vehicle-loaded")
        page().setViewportSize(390, 844)
        loopback.scrollIntoViewIfNeeded()
        overview.watched.screenshot("vehicle-loaded-phone")
        page().setViewportSize(1440, 860)

        loopback.locator("[data-action=reset-load]").click()
        assertThat(page().locator("#toasts")).containsText("Reset load ($vehicle): done")
        overview.watched.screenshot("vehicle-load-reset")
        eventually(20.seconds) { orderState() shouldBeIn setOf("BEING_PROCESSED", "FINISHED") }
        page().locator("#details .close").click()
    }

    browserTest("the load generator panel creates orders between the chosen locations") {
        page().locator("[data-tab=panel-load-generator]").click()
        val panel = page().locator("[data-panel=load-generator]")
        panel.locator("[data-role=from]").selectOption("Storage 01")
        panel.locator("[data-role=to]").selectOption("Goods out 01")
        panel.locator("[data-role=rate]").fill("120")
        panel.locator("[data-role=toggle]").click()
        assertThat(panel.locator("[data-role=status]"))
            .hasText(
                Pattern.compile("Running · created [1-9]"),
                LocatorAssertions.HasTextOptions().setTimeout(10_000.0),
            )
        overview.watched.screenshot("panel-load-generator")
        panel.locator("[data-role=toggle]").click()
        assertThat(panel.locator("[data-role=status]")).containsText("Stopped")
        assertThat(panel.locator("[data-role=error]")).isEmpty()
    }

    browserTest("the statistics panel charts finished orders and vehicle time") {
        page().locator("[data-tab=panel-statistics]").click()
        val panel = page().locator("[data-panel=statistics]")
        assertThat(panel.locator("[data-role=totals]")).hasText(Pattern.compile("Finished: [1-9]"))
        // Park orders replaced by real work end FAILED, but are no failed work: only non-dispensable orders count.
        val failedWork = Json.parseToJsonElement(overview.ktcs.get("/v1/transportOrders").body()).jsonArray
            .map { it.jsonObject }
            .count { order ->
                !order["dispensable"]!!.jsonPrimitive.boolean &&
                    order["state"]!!.jsonPrimitive.content in setOf("FAILED", "UNROUTABLE")
            }
        assertThat(panel.locator("[data-role=totals]")).containsText("failed: $failedWork ·")
        assertThat(panel.locator("[data-role=totals]")).containsText("park/recharge orders (not counted):")
        assertThat(panel.locator("[data-role=per-minute] rect:not([height='0'])").first()).isVisible()
        // A vehicle's row appears only once its time has been counted (the legend is always drawn).
        assertThat(panel.locator("[data-role=activity]"))
            .containsText("Vehicle-01", LocatorAssertions.ContainsTextOptions().setTimeout(10_000.0))
        overview.watched.screenshot("panel-statistics")
    }

    browserTest("the resource allocation panel lists what each vehicle holds") {
        page().locator("[data-tab=panel-resource-allocation]").click()
        val panel = page().locator("[data-panel=resource-allocation]")
        assertThat(panel.locator("[data-role=vehicles] tbody tr")).hasCount(4)
        assertThat(panel.locator("[data-role=vehicles] tbody")).containsText("Vehicle-01")
        assertThat(panel.locator("[data-role=resources] tbody")).containsText("Point-")
        val cells = panel.locator("td").allTextContents().map { cell -> cell.split(", ") }
        cells.filter { it.size != it.toSet().size } shouldBe emptyList()
        overview.watched.screenshot("panel-resources")
    }

    browserTest("after the WebSocket drops, the page resynchronises and the load generator keeps running") {
        val path = longestPath()
        page().locator("#fit").click()
        val (x, y) = position("path", path)!!
        page().mouse().click(x, y)
        val lockedFact = page().locator(
            "#details tr",
        ).filter(Locator.FilterOptions().setHasText("Locked")).locator("td")
        assertThat(lockedFact).hasText("no")
        // The sources and destinations chosen in the load generator test are still selected.
        page().locator("[data-tab=panel-load-generator]").click()
        val generator = page().locator("[data-panel=load-generator]")
        generator.locator("[data-role=rate]").fill("60")
        generator.locator("[data-role=toggle]").click()

        page().evaluate("() => window.ktcsOverview.dropConnection(2000)")
        page().waitForFunction("() => !window.ktcsOverview.connected()")
        // Changed while the page hears nothing: only the snapshots after reconnecting can tell it.
        overview.ktcs.put("/v1/paths/${encode(path)}/locked?newValue=true").statusCode() shouldBe 200
        page().waitForFunction(
            "() => window.ktcsOverview.connected()",
            null,
            Page.WaitForFunctionOptions().setTimeout(10_000.0),
        )
        assertThat(page().locator("#connection")).hasText("live")
        assertThat(lockedFact).hasText("yes")
        (drawn()["vehicles"] as Number).toInt() shouldNotBe 0

        val createdSoFar = CREATED.find(generator.locator("[data-role=status]").textContent())!!.groupValues[1].toInt()
        page().waitForFunction(
            "n => { const m = document.querySelector('[data-panel=load-generator] [data-role=status]').textContent" +
                ".match(/Running · created (\\d+)/); return m !== null && Number(m[1]) > n; }",
            createdSoFar,
            Page.WaitForFunctionOptions().setTimeout(10_000.0),
        )
        assertThat(generator.locator("[data-role=error]")).isEmpty()
        generator.locator("[data-role=toggle]").click()
        assertThat(generator.locator("[data-role=status]")).containsText("Stopped")
        overview.ktcs.put("/v1/paths/${encode(path)}/locked?newValue=false").statusCode() shouldBe 200
        assertThat(lockedFact).hasText("no")
    }

    browserTest("a replaced plant model is announced, closes the details and is drawn") {
        // The kernel replaces the model only when no order runs: withdraw what the load generator left.
        withdrawOpenOrders()
        // A selected order highlights its route; the replacement drops the (final) order, so nothing may stay drawn.
        page().locator("[data-tab=orders]").click()
        page().locator("[data-order='Browser-Order-1']").click()
        assertThat(page().locator("#details h2")).hasText("Order Browser-Order-1")
        drawnNames("highlightedRoute").shouldNotBeEmpty()
        val replacement = JsonObject(model() + ("name" to JsonPrimitive("Replaced demo")))
        overview.ktcs.put("/v1/plantModel", replacement.toString()).statusCode() shouldBe 200
        assertThat(page().locator("#toasts")).containsText("Plant model replaced: Replaced demo")
        assertThat(page().locator("#model-name")).hasText("Replaced demo")
        assertThat(page().locator("#details")).isHidden()
        page().waitForFunction("n => window.ktcsOverview.drawn().points === n", model()["points"]!!.jsonArray.size)
        drawnNames("highlightedRoute").shouldBeEmpty()
        // The bands drawn are exactly what the kernel's vehicles hold now: each its own position, nothing else.
        eventually(10.seconds) {
            val held = heldByVehicles()
            held.size shouldBe 4
            drawnNames("drawnResources") shouldBe held
        }
        drawnNames("drawnRoutes").shouldBeEmpty()
        overview.watched.screenshot("model-replaced")
    }
})
