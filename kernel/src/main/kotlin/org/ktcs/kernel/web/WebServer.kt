package org.ktcs.kernel.web

import io.ktor.serialization.kotlinx.json.json
import io.ktor.server.application.Application
import io.ktor.server.application.install
import io.ktor.server.cio.CIO
import io.ktor.server.engine.EmbeddedServer
import io.ktor.server.engine.embeddedServer
import io.ktor.server.plugins.contentnegotiation.ContentNegotiation
import io.ktor.server.routing.route
import io.ktor.server.routing.routing
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.Json
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings

/** The HTTP server of the kernel application (Ktor, CIO engine). */
class WebServer(private val config: KtcsConfig, private val version: KernelVersion) {
    private var server: EmbeddedServer<*, *>? = null

    /** Starts listening and returns the base URL it serves, with the port actually bound. */
    fun start(): String {
        val host = config[KtcsSettings.webBindAddress]
        val started = embeddedServer(CIO, port = config[KtcsSettings.webPort], host = host) { webModule(version) }
            .start(wait = false)
        server = started
        val port = runBlocking { started.engine.resolvedConnectors().first().port }
        return "http://$host:$port"
    }

    fun stop() {
        server?.stop(gracePeriodMillis = 200, timeoutMillis = 2_000)
        server = null
    }
}

/** Installs the plugins and mounts the routes; also used by tests with Ktor's test host. */
fun Application.webModule(version: KernelVersion) {
    install(ContentNegotiation) { json(Json { encodeDefaults = true }) }
    routing {
        route("/v1") { kernelRoutes(version) }
    }
}
