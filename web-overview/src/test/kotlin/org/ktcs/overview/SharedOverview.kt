package org.ktcs.overview

import io.kotest.matchers.collections.shouldBeEmpty

/**
 * One application (demo plant, loopback vehicles) and one overview page in headless Chromium that a spec's browser
 * tests share, in order; started by the first test that runs, so a spec without Chromium starts nothing.
 */
class SharedOverview {
    var ktcs: RunningKtcs? = null
        private set
    private var session: Chromium.Session? = null
    lateinit var watched: Chromium.WatchedPage
        private set

    /** Starts the application and the page once, runs [body], and fails on any console or page error. */
    suspend fun run(ready: String, body: suspend () -> Unit) {
        Chromium.assumeAvailable()
        if (session == null) {
            ktcs = RunningKtcs()
            session = Chromium.start()
            watched = session!!.newPage()
            watched.page.navigate(ktcs!!.baseUrl + "/")
            watched.page.waitForFunction(ready)
        }
        body()
        watched.errors.shouldBeEmpty()
    }

    fun close() {
        session?.close()
        ktcs?.close()
    }
}
