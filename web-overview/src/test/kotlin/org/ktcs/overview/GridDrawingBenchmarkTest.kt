package org.ktcs.overview

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldMatch
import org.ktcs.kernel.app.LoadedModel
import org.ktcs.kernel.simulation.Fleet
import org.ktcs.kernel.simulation.GridPlant

/**
 * The drawing figure for a large plant: a generated 100x100 grid (10,000 points), drawn with the high-contrast
 * themes. It prints the draw times of zoomed frames (a figure for people, not an assertion) and checks that every
 * point and path is drawn.
 */
class GridDrawingBenchmarkTest : FunSpec({
    test("a 100x100 grid plant is drawn completely; draw times are printed") {
        Chromium.assumeAvailable()
        val model = Fleet.withVehicles(GridPlant(100, 100).build(), 20)
        val themes =
            listOf("overview.vehicleTheme=high-contrast-vehicles", "overview.locationTheme=high-contrast-locations")
        RunningKtcs(themes, LoadedModel(model, "grid 100x100", emptyList())).use { ktcs ->
            Chromium.start().use { session ->
                val watched = session.newPage()
                val page = watched.page
                val started = System.nanoTime()
                page.navigate(ktcs.baseUrl + "/")
                page.waitForFunction("() => window.ktcsOverview && window.ktcsOverview.drawn().points > 0")
                val firstDrawMs = (System.nanoTime() - started) / 1_000_000
                val drawn = page.evaluate("() => window.ktcsOverview.drawn()") as Map<*, *>
                (drawn["points"] as Number).toInt() shouldBe model.points.size
                (drawn["paths"] as Number).toInt() shouldBe model.paths.size
                watched.screenshot("grid-100x100-high-contrast")
                val style = page.evaluate("() => window.ktcsOverview.vehicleStyle('Vehicle-001')") as Map<*, *>
                style["label"].toString() shouldMatch Regex("""Vehicle-001 \d+%""")
                style["stroke"] shouldBe "#000000"
                @Suppress("UNCHECKED_CAST")
                val times = (page.evaluate("() => window.ktcsOverview.benchmark(40)") as List<Number>)
                    .map { it.toDouble() }.sorted()
                println(
                    "overview_grid_points: ${model.points.size}\n" +
                        "overview_grid_paths: ${model.paths.size}\n" +
                        "overview_page_ready_ms: $firstDrawMs\n" +
                        "overview_frame_draw_p50_ms: ${"%.1f".format(times[times.size / 2])}\n" +
                        "overview_frame_draw_p90_ms: ${"%.1f".format(times[times.size * 9 / 10])}\n" +
                        "overview_frame_draw_max_ms: ${"%.1f".format(times.last())}",
                )
                watched.errors.shouldBeEmpty()
            }
        }
    }
})
