package org.ktcs.e2e.plant

import com.microsoft.playwright.Browser
import com.microsoft.playwright.BrowserType
import com.microsoft.playwright.Page
import com.microsoft.playwright.Playwright
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.Collections

/**
 * Debian's headless Chromium, driven by Playwright for Java, as web-overview's browser tests launch it (a copy:
 * e2e-tests cannot use another module's test classes). Where it is missing the browser part of a test is left out
 * with the reason, unless KTCS_REQUIRE_BROWSER=1 (set by CI), where it fails.
 */
object Chromium {
    // -Dktcs.chromium=/elsewhere tries another browser (or shows what happens without one).
    private val executable: Path = Paths.get(System.getProperty("ktcs.chromium", "/usr/bin/chromium"))
    private val required = System.getenv("KTCS_REQUIRE_BROWSER") == "1"

    private val flags = listOf(
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
    )

    /** Why the browser part is left out here, or `null` when it runs (always with KTCS_REQUIRE_BROWSER=1). */
    fun skipReason(): String? = if (Files.isExecutable(executable) || required) {
        null
    } else {
        "$executable is missing: install Debian's chromium package to run the browser part"
    }

    /** Starts Playwright and the browser; close both with [Session.close]. */
    fun start(): Session {
        check(Files.isExecutable(executable)) {
            "KTCS_REQUIRE_BROWSER=1 but $executable is missing: install Debian's chromium package"
        }
        // PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 and playwright.nodejs.path come from the Surefire configuration.
        val playwright = Playwright.create()
        val browser = runCatching {
            playwright.chromium().launch(
                BrowserType.LaunchOptions().setExecutablePath(executable).setHeadless(true).setArgs(flags),
            )
        }.onFailure { playwright.close() }.getOrThrow()
        return Session(playwright, browser)
    }

    class Session(private val playwright: Playwright, private val browser: Browser) : AutoCloseable {
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
        val errors: MutableList<String> = Collections.synchronizedList(mutableListOf())

        init {
            page.onConsoleMessage { if (it.type() == "error") errors += "console: ${it.text()}" }
            page.onPageError { errors += "page error: $it" }
        }

        /** Saves a screenshot as target/screenshots/[name].png of the module and answers its path. */
        fun screenshot(name: String): Path {
            val file = Files.createDirectories(Paths.get("target", "screenshots")).resolve("$name.png")
            page.screenshot(Page.ScreenshotOptions().setPath(file))
            return file
        }
    }
}
