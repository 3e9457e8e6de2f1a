package org.ktcs.overview

import com.microsoft.playwright.Page
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty

/**
 * The real application and one headless Chromium page on its overview, shared by the tests of one spec, in order:
 * the first test that calls [open] starts them and waits until the page answers true to [ready].
 */
class OverviewSession(private val ready: String = "() => window.ktcsOverview && window.ktcsOverview.connected()") {
    private var application: RunningKtcs? = null
    private var session: Chromium.Session? = null
    lateinit var watched: Chromium.WatchedPage
        private set

    val ktcs: RunningKtcs get() = application ?: error("no test has opened the overview yet")
    val page: Page get() = watched.page

    /** Skips the test without Chromium (fails it with `KTCS_REQUIRE_BROWSER=1`); starts everything on first use. */
    fun open() {
        Chromium.assumeAvailable()
        if (session != null) return
        application = RunningKtcs()
        session = Chromium.start()
        watched = session!!.newPage()
        page.navigate(ktcs.baseUrl + "/")
        page.waitForFunction(ready)
    }

    /** A test of [spec] that opens the overview first and fails on any console or page error. */
    fun test(spec: FunSpec, name: String, body: suspend () -> Unit) = spec.test(name) {
        open()
        body()
        watched.errors.shouldBeEmpty()
    }

    fun close() {
        session?.close()
        application?.close()
    }
}
