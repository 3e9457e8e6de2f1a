package org.ktcs.overview

import com.microsoft.playwright.Browser
import com.microsoft.playwright.BrowserType
import com.microsoft.playwright.Page
import com.microsoft.playwright.Playwright
import org.opentest4j.TestAbortedException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/**
 * Debian's headless Chromium, driven by Playwright for Java. Where it is missing the browser tests are skipped
 * with the reason, unless KTCS_REQUIRE_BROWSER=1 (set by CI), where they run and fail.
 */
object Chromium {
    // -Dktcs.chromium=/elsewhere tries another browser (or shows what happens without one).
    private val executable: Path = Paths.get(System.getProperty("ktcs.chromium", "/usr/bin/chromium"))
    private val required = System.getenv("KTCS_REQUIRE_BROWSER") == "1"
    private val missingReason = "$executable is missing: install Debian's chromium package to run the browser tests"

    private val flags = listOf(
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
    )

    /** Skips the running test, with the reason, where Chromium is missing (unless KTCS_REQUIRE_BROWSER=1). */
    fun assumeAvailable() {
        if (!Files.isExecutable(executable) && !required) {
            // Kotest does not hand a skip reason on to the Surefire report, so the test's output carries it.
            System.err.println("browser test skipped: $missingReason")
            throw TestAbortedException(missingReason)
        }
    }

    /** Starts Playwright and the browser; close both with [Session.close]. */
    fun start(): Session {
        check(Files.isExecutable(executable)) {
            "KTCS_REQUIRE_BROWSER=1 but $executable is missing: install Debian's chromium package"
        }
        // PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 and playwright.nodejs.path come from the Surefire configuration.
        val playwright = Playwright.create()
        val browser = playwright.chromium().launch(
            BrowserType.LaunchOptions().setExecutablePath(executable).setHeadless(true).setArgs(flags),
        )
        return Session(playwright, browser)
    }

    class Session(private val playwright: Playwright, val browser: Browser) : AutoCloseable {
        /** A page of the given size that records every console error and uncaught page error. */
        fun newPage(width: Int = 1440, height: Int = 860): WatchedPage {
            val context = browser.newContext(Browser.NewContextOptions().setViewportSize(width, height))
            return WatchedPage(context.newPage())
        }

        override fun close() {
            browser.close()
            playwright.close()
        }
    }

    class WatchedPage(val page: Page) {
        val errors: MutableList<String> = java.util.Collections.synchronizedList(mutableListOf())

        init {
            page.onConsoleMessage { if (it.type() == "error") errors += "console: ${it.text()}" }
            page.onPageError { errors += "page error: $it" }
        }

        fun screenshot(name: String) {
            val directory = Paths.get("target", "screenshots")
            Files.createDirectories(directory)
            page.screenshot(Page.ScreenshotOptions().setPath(directory.resolve("$name.png")))
        }
    }
}
