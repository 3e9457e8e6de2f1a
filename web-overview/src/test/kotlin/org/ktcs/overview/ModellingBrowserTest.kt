package org.ktcs.overview

import com.microsoft.playwright.Page
import com.microsoft.playwright.assertions.LocatorAssertions
import com.microsoft.playwright.assertions.PlaywrightAssertions.assertThat
import com.microsoft.playwright.options.FilePayload
import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.kernel.app.PlantModelLoader
import java.nio.file.Files
import kotlin.time.Duration.Companion.seconds

/**
 * The overview's modelling mode in headless Chromium against the real application: a plant drawn from nothing by
 * mouse and keyboard runs an order, edits undo and redo, an invalid model is refused with its error on the element,
 * the published model survives a restart, and a file opened and saved is byte for byte the same. The tests share
 * one page and run in order.
 */
class ModellingBrowserTest : FunSpec({
    val dataDirectory = Files.createTempDirectory("ktcs-modelling-test")
    var ktcs: RunningKtcs? = null
    var session: Chromium.Session? = null
    lateinit var watched: Chromium.WatchedPage
    val page: () -> Page = { watched.page }
    val settings = listOf("dispatcher.parkIdleVehicles=false")

    fun openOverview() {
        ktcs = RunningKtcs(settings, dataDirectory = dataDirectory)
        page().navigate(ktcs!!.baseUrl + "/")
        page().waitForFunction("() => window.ktcsOverview && window.ktcsOverview.connected()")
    }

    fun browserTest(name: String, body: suspend () -> Unit) = test(name) {
        Chromium.assumeAvailable()
        if (session == null) {
            session = Chromium.start()
            watched = session!!.newPage(1440, 860)
            page().onDialog { it.accept() }
            openOverview()
        }
        body()
        watched.errors.shouldBeEmpty()
    }
    afterSpec {
        session?.close()
        ktcs?.close()
        dataDirectory.toFile().deleteRecursively()
    }

    fun kernelModel(): JsonObject = Json.parseToJsonElement(ktcs!!.get("/v1/plantModel").body()).jsonObject
    fun draft(
        expression: String,
    ): Any? = page().evaluate("() => { const m = window.ktcsOverview.modelling.mode; return $expression; }")

    /**
     * Waits until the mode just switched to has its draft and has drawn it twice: the side panel it opens resizes the
     * plant, and a position asked for before that is off by the resize (a loaded machine made a click meant for a
     * point hit the path beside it).
     */
    fun settled() {
        page().waitForFunction("() => window.ktcsOverview.modelling.mode.draft?.model?.points?.length > 0")
        page().evaluate(
            "() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(() => done(null))))",
        )
    }

    /** Clicks the plant canvas at (x, y) from its top left corner. */
    fun clickPlant(x: Int, y: Int) {
        val box = page().locator(".plant-overlay").boundingBox()
        page().mouse().click(box.x + x, box.y + y)
    }

    /** Where the plant view draws element [name] of [kind], in page coordinates. */
    fun pagePosition(kind: String, name: String): Pair<Double, Double> {
        val at = page().evaluate(
            "([k, n]) => window.ktcsOverview.pagePositionOf(k, n)",
            listOf(kind, name),
        ) as Map<*, *>
        return (at["x"] as Number).toDouble() to (at["y"] as Number).toDouble()
    }

    /** Clicks element [name] of [kind] where the plant view draws it. */
    fun clickElement(kind: String, name: String) {
        val (x, y) = pagePosition(kind, name)
        page().mouse().click(x, y)
    }

    /** Control point [index] of the list [controls] (a draft expression), in page coordinates (layout units of 50 mm). */
    fun handlePosition(controls: String, index: Int): Pair<Double, Double> {
        val at = page().evaluate(
            "() => { const m = window.ktcsOverview.modelling.mode; const c = $controls[$index];" +
                " const s = m.plant.view.toScreen(c.x * 50, -c.y * 50);" +
                " const r = m.plant.canvas.getBoundingClientRect(); return [r.left + s.x, r.top + s.y]; }",
        ) as List<*>
        return (at[0] as Number).toDouble() to (at[1] as Number).toDouble()
    }

    val corners = listOf(150 to 150, 450 to 150, 450 to 450, 150 to 450)

    browserTest("a plant drawn from an empty model by mouse and keyboard is published and runs an order to FINISHED") {
        page().locator("#mode-modelling").click()
        page().locator("[data-action=new]").click()
        draft("m.draft.model.points.length") shouldBe 0
        page().keyboard().press("p")
        corners.forEach { (x, y) -> clickPlant(x, y) }
        page().keyboard().press("a")
        corners.indices.forEach { i ->
            clickPlant(corners[i].first, corners[i].second)
            clickPlant(corners[(i + 1) % 4].first, corners[(i + 1) % 4].second)
        }
        page().keyboard().press("l")
        clickPlant(600, 450)
        page().keyboard().press("a")
        clickPlant(600, 450)
        clickPlant(450, 450) // the link to Point-0003
        page().keyboard().press("Escape")
        page().locator("[data-add=vehicle]").click()
        // The loopback vehicle starts at Point-0001 (its property loopback:initialPosition).
        page().locator("[name=new-property-key]").fill("loopback:initialPosition")
        page().locator("[name=new-property-value]").fill("Point-0001")
        page().locator(".add-property button").click()
        draft("m.draft.model.points.length") shouldBe 4
        draft("m.draft.model.paths.length") shouldBe 4
        draft("m.draft.model.locations[0].links[0].pointName") shouldBe "Point-0003"
        watched.screenshot("modelling-drawn")

        page().locator("[data-action=publish]").click()

        eventually(10.seconds) { kernelModel()["name"]!!.jsonPrimitive.content shouldBe "Unnamed model" }
        kernelModel()["vehicles"]!!.jsonArray.map { it.jsonObject["name"]!!.jsonPrimitive.content } shouldContainExactly
            listOf("Vehicle-0001")
        page().locator("#mode-operating").click()
        page().locator("[data-tab=orders]").click()
        page().locator("[data-action=new-order]").click()
        val dialog = page().locator("#order-dialog")
        dialog.locator("[name=destination]").selectOption("location:Location-0001")
        dialog.locator("[name=operation]").selectOption("NOP")
        dialog.locator("[name=name]").fill("Drawn-Plant-Order")
        dialog.locator("[data-action=create-order]").click()
        val state = page().locator("[data-order='Drawn-Plant-Order'] [data-column=state]")
        assertThat(state).hasText("FINISHED", LocatorAssertions.HasTextOptions().setTimeout(60_000.0))
    }

    browserTest("every edit undoes and redoes: a move by arrow key, a deletion with the paths at the point") {
        page().locator("#mode-modelling").click()
        page().keyboard().press("s")
        settled()
        clickElement("point", "Point-0001")
        draft("[...m.selection]") shouldBe listOf("point:Point-0001")
        val x = (draft("m.draft.model.points[0].position.x") as Number).toInt()

        page().keyboard().press("ArrowRight")
        (draft("m.draft.model.points[0].position.x") as Number).toInt() shouldBe x + 500
        page().keyboard().press("Control+z")
        (draft("m.draft.model.points[0].position.x") as Number).toInt() shouldBe x
        page().keyboard().press("Control+y")
        (draft("m.draft.model.points[0].position.x") as Number).toInt() shouldBe x + 500
        page().keyboard().press("Delete")
        draft("m.draft.model.paths.length") shouldBe 2
        page().locator("[data-action=undo]").click()
        draft("m.draft.model.paths.length") shouldBe 4
        page().locator("[data-action=undo]").click()
        (draft("m.draft.model.points[0].position.x") as Number).toInt() shouldBe x

        // Dragged by the mouse: moved on the grid, once the button is released (one edit, one undo).
        val (px, py) = pagePosition("point", "Point-0001")
        page().mouse().move(px, py)
        page().mouse().down()
        page().mouse().move(px + 80, py, com.microsoft.playwright.Mouse.MoveOptions().setSteps(4))
        page().mouse().up()
        val dragged = (draft("m.draft.model.points[0].position.x") as Number).toInt()
        (dragged > x) shouldBe true
        (dragged - x) % 500 shouldBe 0
        page().keyboard().press("Control+z")
        (draft("m.draft.model.points[0].position.x") as Number).toInt() shouldBe x
    }

    browserTest("a path becomes a Bezier curve whose control point is dragged by its handle; undo straightens it") {
        val path = "Point-0002 --- Point-0003"
        clickElement("path", path)
        page().locator("select[name='layout.connectionType']").selectOption("BEZIER")
        val controls = "m.draft.model.paths.find((p) => p.name === '$path').layout.controlPoints"
        draft("$controls.length") shouldBe 2
        val (hx, hy) = handlePosition(controls, 0)
        val before = draft("JSON.stringify($controls[0])")

        page().mouse().move(hx, hy)
        page().mouse().down()
        page().mouse().move(hx + 60, hy + 10, com.microsoft.playwright.Mouse.MoveOptions().setSteps(5))
        page().mouse().up()

        draft("JSON.stringify($controls[0])") shouldNotBe before
        draft("$controls.length") shouldBe 2
        page().keyboard().press("Control+z")
        draft("JSON.stringify($controls[0])") shouldBe before
        page().keyboard().press("Control+z")
        draft("$controls.length") shouldBe 0

        // BEZIER_3: five control points along the straight line (layout units: x / 50, -y / 50), the middle one dragged.
        page().locator("select[name='layout.connectionType']").selectOption("BEZIER_3")
        val ends = "['Point-0002', 'Point-0003'].map((n) => m.draft.model.points.find((p) => p.name === n).position)"
        draft(
            "(() => { const [a, b] = $ends; return $controls.every((c, i) => " +
                "Math.abs(c.x - (a.x + (b.x - a.x) * (i + 1) / 6) / 50) <= 1 && " +
                "Math.abs(c.y + (a.y + (b.y - a.y) * (i + 1) / 6) / 50) <= 1); })()",
        ) shouldBe true
        draft("$controls.length") shouldBe 5
        val (mx, my) = handlePosition(controls, 2)
        page().mouse().move(mx, my)
        page().mouse().down()
        page().mouse().move(mx + 50, my, com.microsoft.playwright.Mouse.MoveOptions().setSteps(5))
        page().mouse().up()
        ((draft("$controls[2].x") as Number).toInt() > (draft("$controls[1].x") as Number).toInt()) shouldBe true
        watched.screenshot("modelling-curve")

        // ELBOW: without control points; once its ends are no longer in line, drawn as an axis-parallel dog-leg.
        page().locator("select[name='layout.connectionType']").selectOption("ELBOW")
        draft("$controls.length") shouldBe 0
        val line = "m.plant.geometry.pathsByName.get('$path').line"
        draft("$line.length") shouldBe 2
        clickElement("point", "Point-0003")
        page().keyboard().press("ArrowRight")
        draft("$line.length") shouldBe 4
        draft("$line.every((p, i, l) => i === 0 || p.x === l[i - 1].x || p.y === l[i - 1].y)") shouldBe true
        // A vehicle reported half-way along the straight line between the ends is drawn half-way along the dog-leg.
        draft(
            "(() => { const p = m.plant.geometry.pathsByName.get('$path'); const l = p.line;" +
                " const half = { x: (p.src.x + p.dst.x) / 2, y: (p.src.y + p.dst.y) / 2 };" +
                " const at = m.plant.vehicles.positionOf({ pose: { position: half, orientationAngle: 0 }," +
                " allocatedResources: [['$path']] });" +
                " return Math.abs(at.x - (l[1].x + l[2].x) / 2) < 1 && Math.abs(at.y - l[1].y) < 1; })()",
        ) shouldBe true
        repeat(4) { page().keyboard().press("Control+z") }
        draft("m.draft.model.paths.find((p) => p.name === '$path').layout.connectionType") shouldBe "DIRECT"
        page().keyboard().press("Escape")
    }

    browserTest(
        "a vehicle copied in the side bar is pasted as the next vehicle; its order types are the running one's",
    ) {
        page().keyboard().press("Escape")
        page().locator(".list-vehicle button.link", Page.LocatorOptions().setHasText("Vehicle-0001")).click()
        page().keyboard().press("Control+c")
        page().keyboard().press("Control+v")
        draft("[...m.selection]") shouldBe listOf("vehicle:Vehicle-0002")
        draft("m.draft.model.vehicles[1].properties[0].name") shouldBe "loopback:initialPosition"
        page().keyboard().press("Control+z")
        draft("m.draft.model.vehicles.length") shouldBe 1

        // Acceptable order types belong to the running vehicle (openTCS keeps them out of the model): saved at once.
        page().locator(".list-vehicle button.link", Page.LocatorOptions().setHasText("Vehicle-0001")).click()
        val types = page().locator("[name=acceptable-order-types]")
        types.fill("Transport:x")
        assertThat(page().locator(".order-types .field-error")).containsText("whole-number priority")
        types.fill("Transport:0, Park:1")
        page().locator("[data-action=save-order-types]").click()
        eventually(10.seconds) {
            val vehicle = Json.parseToJsonElement(ktcs!!.get("/v1/vehicles/Vehicle-0001").body()).jsonObject
            vehicle["acceptableOrderTypes"]!!.jsonArray.map { it.jsonObject["name"]!!.jsonPrimitive.content } shouldBe
                listOf("Transport", "Park")
        }
        page().keyboard().press("Escape")
    }

    browserTest("a point put on a new layer disappears when the layer is hidden; undo brings it back") {
        page().keyboard().press("Escape")
        page().locator("[data-add=layer]").click()
        draft("m.draft.model.visualLayout.layers.length") shouldBe 2
        // Each click changes the side bar, which may resize the plant before the next position is asked for; the
        // points are the top ones, away from the corner where the previous test's toast may still stand.
        settled()
        clickElement("point", "Point-0002")
        eventually(5.seconds) { draft("[...m.selection]") shouldBe listOf("point:Point-0002") }
        settled()
        page().keyboard().down("Shift")
        clickElement("point", "Point-0001")
        page().keyboard().up("Shift")
        eventually(5.seconds) { draft("m.selection.size") shouldBe 2 }
        page().locator("select[name=selection-layer]").selectOption("1")
        draft("m.draft.model.points.filter((p) => p.layout.layerId === 1).length") shouldBe 2
        page().keyboard().press("Escape")
        watched.screenshot("modelling-layers")
        for (width in listOf(1024, 390)) {
            page().setViewportSize(width, 860)
            watched.screenshot("modelling-layers-$width")
        }
        page().setViewportSize(1440, 860)
        page().locator("[data-layer='1'] [name=layer-visible]").uncheck()
        draft("m.plant.isVisible(m.plant.geometry.points.get('Point-0002'))") shouldBe false
        draft("m.plant.elementsInView().points.length") shouldBe 2
        page().locator("[data-layer='1'] [name=layer-visible]").check()
        page().locator("[data-layer-group='0'] [name=layer-group-visible]").uncheck()
        draft("m.plant.elementsInView().points.length") shouldBe 0
        repeat(5) { page().keyboard().press("Control+z") }
        draft("m.draft.model.visualLayout.layers.length") shouldBe 1
        draft("m.activeLayer") shouldBe 0
        draft("m.plant.elementsInView().points.length") shouldBe 4
    }

    browserTest("a model with an error is refused with the error shown on the element; the kernel keeps its model") {
        clickElement("location", "Location-0001")
        draft("[...m.selection]") shouldBe listOf("location:Location-0001")
        page().locator("[name='link-Point-0003']").fill("FLY")
        page().locator("[name='link-Point-0003']").press("Enter")
        page().locator(".plant-overlay").focus()
        page().waitForFunction(
            "() => window.ktcsOverview.modelling.mode.overlay.marked.get('Location-0001') === 'ERROR'",
        )
        assertThat(page().locator(".problems")).containsText("FLY")
        watched.screenshot("modelling-error")

        page().locator("[data-action=publish]").click()

        assertThat(page().locator(".toast.error").last()).containsText("Not published")
        kernelModel()["locations"]!!.jsonArray.first().jsonObject["links"]!!.jsonArray.first()
            .jsonObject["allowedOperations"]!!.jsonArray.size shouldBe 0
        page().keyboard().press("Control+z")
        page().waitForFunction("() => window.ktcsOverview.modelling.mode.overlay.marked.size === 0")
    }

    browserTest("a shift-dragged box selects the square; copied and pasted, it comes with its paths; undo removes it") {
        val (x1, y1) = pagePosition("point", "Point-0001")
        val (x3, y3) = pagePosition("point", "Point-0003")
        page().keyboard().press("s")
        page().keyboard().down("Shift")
        page().mouse().move(minOf(x1, x3) - 10, minOf(y1, y3) - 10)
        page().mouse().down()
        page().mouse().move(
            maxOf(x1, x3) + 10,
            maxOf(y1, y3) + 10,
            com.microsoft.playwright.Mouse.MoveOptions().setSteps(4),
        )
        page().mouse().up()
        page().keyboard().up("Shift")
        draft("m.selection.size") shouldBe 8 // 4 points, 4 paths

        page().keyboard().press("Control+c")
        page().keyboard().press("Control+v")

        draft("m.draft.model.points.length") shouldBe 8
        draft("m.draft.model.paths.length") shouldBe 8
        draft("[...m.selection].filter((k) => k.startsWith('point:')).sort()") shouldBe
            listOf("point:Point-0005", "point:Point-0006", "point:Point-0007", "point:Point-0008")
        page().keyboard().press("Control+z")
        draft("m.draft.model.points.length") shouldBe 4
    }

    browserTest("unpublished edits survive a reload of the page") {
        page().keyboard().press("p")
        clickPlant(300, 300)
        page().keyboard().press("s")
        draft("m.draft.model.points.length") shouldBe 5
        page().waitForFunction(
            "() => JSON.parse(localStorage.getItem('ktcs.modelling.draft'))?.model.points.length === 5",
        )

        page().reload()
        page().waitForFunction("() => window.ktcsOverview && window.ktcsOverview.connected()")
        page().locator("#mode-modelling").click()
        page().waitForFunction("() => window.ktcsOverview.modelling.mode?.active")

        draft("m.draft.model.points.length") shouldBe 5
        draft("m.draft.edited") shouldBe true
        assertThat(page().locator(".draft-state")).containsText("unpublished edits")
    }

    browserTest("the demo plant's file opened and saved again is byte for byte the same") {
        val demo = PlantModelLoader::class.java.getResourceAsStream(PlantModelLoader.DEMO_RESOURCE)!!.readAllBytes()
        page().locator("[name=model-file]").setInputFiles(FilePayload("ktcs-demo.xml", "application/xml", demo))
        page().waitForFunction("() => window.ktcsOverview.modelling.mode.draft.model.name === 'kTCS Demo'")

        val download = page().waitForDownload { page().locator("[data-action=save]").click() }

        Files.readAllBytes(download.path()) shouldBe demo
    }

    browserTest("a published model survives a restart of kTCS") {
        // Left first: a page open on a stopped kTCS tries to reconnect, and the browser logs each refusal as an error.
        page().navigate("about:blank")
        ktcs!!.close()
        openOverview()
        kernelModel()["name"]!!.jsonPrimitive.content shouldBe "Unnamed model"
        ktcs!!.get("/v1/plantModel").body() shouldContain "loopback:initialPosition"
        assertThat(page().locator("#model-name")).hasText("Unnamed model")
    }
})
