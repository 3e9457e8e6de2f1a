package org.ktcs.kernel.web

import io.ktor.http.HttpStatusCode
import io.ktor.serialization.kotlinx.json.json
import io.ktor.server.application.Application
import io.ktor.server.application.install
import io.ktor.server.cio.CIO
import io.ktor.server.engine.EmbeddedServer
import io.ktor.server.engine.embeddedServer
import io.ktor.server.plugins.contentnegotiation.ContentNegotiation
import io.ktor.server.response.respond
import io.ktor.server.routing.post
import io.ktor.server.routing.route
import io.ktor.server.routing.routing
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.events.SubscriberTooSlowException
import org.ktcs.kernel.web.plugins.AccessKey
import org.ktcs.kernel.web.plugins.installErrorResponses
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.StatusEventBuffer
import org.ktcs.kernel.web.v1.events.eventRoutes
import org.ktcs.kernel.web.v1.orders.orderSequenceRoutes
import org.ktcs.kernel.web.v1.orders.transportOrderRoutes
import org.ktcs.kernel.web.v1.plantmodel.plantModelRoutes
import org.ktcs.kernel.web.v1.vehicles.vehicleRoutes
import org.slf4j.LoggerFactory

/** Asks the application to shut down, as `DELETE /v1/kernel` does. */
fun interface ShutdownRequest {
    fun request()
}

/** The HTTP server of the kernel application (Ktor, CIO engine). */
class WebServer(
    private val config: KtcsConfig,
    private val version: KernelVersion,
    private val services: KernelServices,
    private val shutdown: ShutdownRequest,
) {
    private var server: EmbeddedServer<*, *>? = null

    /** Starts listening and returns the base URL it serves, with the port actually bound. */
    fun start(): String {
        val host = config[KtcsSettings.webBindAddress]
        val accessKey = config[KtcsSettings.webAccessKey]
        val started = embeddedServer(CIO, port = config[KtcsSettings.webPort], host = host) {
            webModule(version, services, accessKey, shutdown)
        }
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
fun Application.webModule(
    version: KernelVersion,
    services: KernelServices,
    accessKey: String = "",
    shutdown: ShutdownRequest = ShutdownRequest {},
) {
    install(ContentNegotiation) { json(V1Json.json) }
    installErrorResponses()
    val statusEvents = StatusEventBuffer()
    launch { feed(statusEvents, services) }
    routing {
        route("/v1") {
            install(AccessKey) { key = accessKey }
            kernelRoutes(version, shutdown)
            transportOrderRoutes(services)
            orderSequenceRoutes(services)
            vehicleRoutes(services)
            plantModelRoutes(services)
            eventRoutes(services, statusEvents)
            post("/dispatcher/trigger") {
                services.dispatcher.dispatch()
                call.respond(HttpStatusCode.OK)
            }
        }
    }
}

// Keeps the long-polling buffer filled for as long as the server runs; after falling behind it subscribes again.
private suspend fun feed(buffer: StatusEventBuffer, services: KernelServices) {
    while (true) {
        try {
            services.events().collect(buffer::add)
        } catch (error: SubscriberTooSlowException) {
            LoggerFactory.getLogger(
                "org.ktcs.kernel.web",
            ).warn("status events for GET /v1/events fell behind; some were lost")
        }
    }
}
