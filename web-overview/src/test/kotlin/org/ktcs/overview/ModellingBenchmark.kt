package org.ktcs.overview

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.app.LoadedModel
import org.ktcs.kernel.simulation.Fleet
import org.ktcs.kernel.simulation.GridPlant

/**
 * The modelling mode's figures for a large plant: a generated 100x100 grid (10,000 points) opened in the modelling
 * mode of headless Chromium; it prints the frame time (whole plant in view), the time a click takes to select a point
 * and draw the frame, and the time of each drag step moving a selection of points (the model moved, its drawing
 * rebuilt and the frame drawn). Not part of the test suite (it takes a while); run it with
 * `KTCS_BENCH=modelling ./mvnw -B -q verify -pl web-overview -am -Dtest=ModellingBenchmark
 * -Dsurefire.failIfNoSpecifiedTests=false -Dspotless.check.skip=true` (or `web-overview/bench-modelling.sh`).
 */
class ModellingBenchmark : FunSpec({
    test("editing a 100x100 grid plant in the modelling mode; times are printed").config(
        enabled = System.getenv("KTCS_BENCH") == "modelling",
    ) {
        Chromium.assumeAvailable()
        val model = Fleet.withVehicles(GridPlant(100, 100).build(), 20)
        RunningKtcs(model = LoadedModel(model, "grid 100x100", emptyList())).use { ktcs ->
            Chromium.start().use { session ->
                val watched = session.newPage(1440, 860)
                val page = watched.page
                page.navigate(ktcs.baseUrl + "/")
                page.waitForFunction("() => window.ktcsOverview && window.ktcsOverview.drawn().points > 0")
                page.locator("#mode-modelling").click()
                page.waitForFunction("() => window.ktcsOverview.modelling.mode?.active")
                (page.evaluate("() => window.ktcsOverview.modelling.mode.draft.model.points.length") as Number)
                    .toInt() shouldBe model.points.size
                @Suppress("UNCHECKED_CAST")
                val figures = page.evaluate(MEASURE) as Map<String, List<Number>>
                val lines = figures.map { (name, values) ->
                    val sorted = values.map { it.toDouble() }.sorted()
                    "modelling_${name}_ms: min ${"%.1f".format(sorted.first())} " +
                        "median ${"%.1f".format(sorted[sorted.size / 2])} max ${"%.1f".format(sorted.last())} " +
                        "(${sorted.size} runs)"
                }
                println("modelling_points: ${model.points.size}\nmodelling_paths: ${model.paths.size}")
                println(lines.joinToString("\n"))
                watched.errors.shouldBeEmpty()
            }
        }
    }
}) {
    private companion object {
        // Runs in the page: the same calls the pointer makes, each followed by drawing the frame it asks for.
        val MEASURE = """
            () => {
              const mode = window.ktcsOverview.modelling.mode;
              const plant = mode.plant;
              const timed = (action) => { const t = performance.now(); action(); plant.drawFrame(performance.now()); return performance.now() - t; };
              plant.userMoved = false; plant.fit();
              const frame = [];
              for (let i = 0; i < 20; i += 1) frame.push(timed(() => { plant.view.zoomAt(i % 2 ? 1.1 : 1 / 1.1, plant.width / 2, plant.height / 2); plant.staticDirty = true; }));
              plant.fit();
              const points = mode.draft.model.points;
              const select = [];
              for (let i = 0; i < 20; i += 1) {
                const point = plant.geometry.points.get(points[(i * 997) % points.length].name);
                const at = plant.view.toScreen(point.x, point.y);
                const event = { offsetX: at.x, offsetY: at.y, shiftKey: false };
                select.push(timed(() => { mode.pointerDown(event); mode.pointerUp(event); }));
                if (!mode.selection.has('point:' + point.name)) throw new Error('the click did not select ' + point.name);
              }
              const first = plant.geometry.points.get(points[5050].name);
              const at = plant.view.toScreen(first.x, first.y);
              mode.select(points.slice(5000, 5100).map((p) => 'point:' + p.name));
              mode.setTool('select');
              mode.pointerDown({ offsetX: at.x, offsetY: at.y, shiftKey: false });
              const drag = [];
              for (let i = 1; i <= 20; i += 1) drag.push(timed(() => mode.pointerMove({ offsetX: at.x + i * 6, offsetY: at.y + i * 3, shiftKey: false })));
              const drop = [timed(() => mode.pointerUp({ offsetX: at.x + 120, offsetY: at.y + 60, shiftKey: false }))];
              if (mode.draft.model.points[5050].position.x === points[5050].position.x) throw new Error('the drag moved nothing');
              return { frame, select, drag_step: drag, drop };
            }
        """.trimIndent()
    }
}
