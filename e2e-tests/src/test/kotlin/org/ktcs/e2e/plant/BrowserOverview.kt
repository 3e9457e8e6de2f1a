package org.ktcs.e2e.plant

import com.microsoft.playwright.Page
import com.microsoft.playwright.assertions.LocatorAssertions
import com.microsoft.playwright.assertions.PlaywrightAssertions.assertThat
import io.kotest.assertions.withClue
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PlantModel

/**
 * Drives the browser overview of a running kTCS in headless Chromium as an operator would: the page goes live and
 * draws the whole [model], the example extension's vehicle theme and panel load from its jar, and an order created
 * in the create-order dialog reaches FINISHED in the order table. Any console error, page error or error message
 * the page shows its operator fails it.
 */
class BrowserOverview(private val web: String, private val model: PlantModel) {
    /** Runs the whole visit; [onOrderCreated] gets the name of the order the dialog created as soon as it exists. */
    fun visit(onOrderCreated: (String) -> Unit) {
        val started = System.nanoTime()
        Chromium.start().use { session ->
            val watched = session.newPage()
            watched.page.addInitScript(RECORD_ERROR_MESSAGES)
            try {
                visit(watched.page, onOrderCreated)
            } finally {
                runCatching { watched.screenshot(SCREENSHOT) }
                    .onFailure { println("whole plant: no screenshot of the overview: $it") }
            }
            withClue("errors in the browser overview") {
                (watched.errors + errorMessages(watched.page)).shouldBeEmpty()
            }
        }
        println("whole plant: the browser overview's visit took ${(System.nanoTime() - started) / 1_000_000} ms")
    }

    private fun visit(page: Page, onOrderCreated: (String) -> Unit) {
        page.navigate("$web/")
        page.waitForFunction("() => window.ktcsOverview && window.ktcsOverview.connected()")
        assertThat(page.locator("#connection")).hasText("live")
        checkPlantDrawn(page)
        checkExampleTheme(page)
        checkExamplePanel(page)
        createOrder(page)
        onOrderCreated(ORDER)
        val state = page.locator("[data-order='$ORDER'] [data-column=state]")
        assertThat(state).hasText("FINISHED", LocatorAssertions.HasTextOptions().setTimeout(FINISH_TIMEOUT_MS))
    }

    private fun checkPlantDrawn(page: Page) {
        page.waitForFunction(
            "n => window.ktcsOverview.drawn().points === n",
            model.points.size,
            Page.WaitForFunctionOptions().setTimeout(WAIT_TIMEOUT_MS),
        )
        // Every vehicle is drawn once it reports a position, the extension driver's one included.
        page.waitForFunction(
            "n => window.ktcsOverview.drawn().vehicles === n",
            model.vehicles.size,
            Page.WaitForFunctionOptions().setTimeout(WAIT_TIMEOUT_MS),
        )
        val drawn = page.evaluate("() => window.ktcsOverview.drawn()") as Map<*, *>
        (drawn["paths"] as Number).toInt() shouldBe model.paths.size
        (drawn["locations"] as Number).toInt() shouldBe model.locations.size
        assertThat(page.locator("#plant-summary")).containsText("${model.points.size} points")
    }

    /** The example's "energy" theme (overview.vehicleTheme=energy) labels each vehicle with its energy level. */
    private fun checkExampleTheme(page: Page) {
        page.waitForFunction(
            "() => /^Tcp-01 \\d+%$/.test(window.ktcsOverview.vehicleStyle('Tcp-01')?.label ?? '')",
            null,
            Page.WaitForFunctionOptions().setTimeout(WAIT_TIMEOUT_MS),
        )
    }

    /** The example's "Fleet energy" panel has its tab and lists every vehicle. */
    private fun checkExamplePanel(page: Page) {
        page.locator("[data-tab=panel-fleet-energy]").click()
        val rows = page.locator("[data-panel=fleet-energy] table tr")
        assertThat(rows).hasCount(model.vehicles.size)
        assertThat(page.locator("[data-panel=fleet-energy] table")).containsText("Tcp-01")
    }

    private fun createOrder(page: Page) {
        page.locator("[data-tab=orders]").click()
        page.locator("[data-action=new-order]").click()
        val dialog = page.locator("#order-dialog")
        dialog.locator("[name=destination]").selectOption("location:Goods in south 01")
        dialog.locator("[name=operation]").selectOption("Load cargo")
        dialog.getByText("+ Destination").click()
        dialog.locator("[name=destination]").nth(1).selectOption("location:Storage 01")
        dialog.locator("[name=operation]").nth(1).selectOption("Unload cargo")
        dialog.locator("[name=name]").fill(ORDER)
        dialog.locator("[data-action=create-order]").click()
        assertThat(page.locator("[data-order='$ORDER']")).isVisible()
    }

    private fun errorMessages(page: Page): List<String> =
        (page.evaluate("() => window.ktcsErrorMessages ?? []") as List<*>).map { "shown to the operator: $it" }

    companion object {
        const val ORDER = "Browser-1"
        const val SCREENSHOT = "whole-plant"
        private const val WAIT_TIMEOUT_MS = 20_000.0

        // The order queues behind the REST and XML orders: it finished about 31 s after creation on 2 shared cores.
        private const val FINISH_TIMEOUT_MS = 50_000.0

        // The page reports a panel or theme that fails to load only as an error toast, which vanishes after 15 s.
        private val RECORD_ERROR_MESSAGES = """
            window.ktcsErrorMessages = [];
            new MutationObserver((changes) => changes.forEach((change) => change.addedNodes.forEach((node) => {
              if (node.classList?.contains('toast') && node.classList.contains('error')) {
                window.ktcsErrorMessages.push(node.textContent);
              }
            }))).observe(document, { childList: true, subtree: true });
        """.trimIndent()
    }
}
