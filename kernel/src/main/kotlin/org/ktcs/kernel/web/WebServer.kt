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
import io.ktor.server.websocket.WebSockets
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.events.SubscriberTooSlowException
import org.ktcs.kernel.web.docs.ApiDocument
import org.ktcs.kernel.web.docs.docsRoutes
import org.ktcs.kernel.web.docs.openApiRoutes
import org.ktcs.kernel.web.plugins.AccessKey
import org.ktcs.kernel.web.plugins.Cors
import org.ktcs.kernel.web.plugins.RequestSizeLimit
import org.ktcs.kernel.web.plugins.installErrorResponses
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.StatusEventBuffer
import org.ktcs.kernel.web.v1.events.eventRoutes
import org.ktcs.kernel.web.v1.orders.orderSequenceRoutes
import org.ktcs.kernel.web.v1.orders.transportOrderRoutes
import org.ktcs.kernel.web.v1.plantmodel.plantModelRoutes
import org.ktcs.kernel.web.v1.vehicles.vehicleRoutes
import org.ktcs.kernel.web.ws.webSocketRoutes
import org.slf4j.LoggerFactory

/** What the web API's plugins are set to (from the `web.*` settings). */
data class WebOptions(
    val accessKey: String = "",
    val allowedOrigins: String = "*",
    val maxRequestBodyBytes: Long = 200L * 1024 * 1024,
    val webSocketBufferSize: Int = 1000,
)

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
    private val contributions: List<WebContribution> = emptyList(),
) {
    private var server: EmbeddedServer<*, *>? = null

    /** Starts listening and returns the base URL it serves, with the port actually bound. */
    fun start(): String {
        val host = config[KtcsSettings.webBindAddress]
        val options = WebOptions(
            accessKey = config[KtcsSettings.webAccessKey],
            allowedOrigins = config[KtcsSettings.webAllowedOrigins],
            maxRequestBodyBytes = config[KtcsSettings.webMaxRequestBodySize] * 1024 * 1024,
            webSocketBufferSize = config[KtcsSettings.webSocketBufferSize],
        )
        val started = embeddedServer(CIO, port = config[KtcsSettings.webPort], host = host) {
            webModule(version, services, options, shutdown, contributions)
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
    options: WebOptions = WebOptions(),
    shutdown: ShutdownRequest = ShutdownRequest {},
    contributions: List<WebContribution> = emptyList(),
) {
    install(ContentNegotiation) { json(V1Json.json) }
    installErrorResponses()
    install(Cors) { allowedOrigins = options.allowedOrigins }
    install(RequestSizeLimit) { maxBytes = options.maxRequestBodyBytes }
    install(WebSockets)
    val statusEvents = StatusEventBuffer()
    launch { feed(statusEvents, services) }
    val document = lazy { ApiDocument.current }
    routing {
        contributions.forEach { it.install(this) }
        docsRoutes(document)
        route("/v1") {
            install(AccessKey) { key = options.accessKey }
            openApiRoutes(document)
            kernelRoutes(version, shutdown)
            transportOrderRoutes(services)
            orderSequenceRoutes(services)
            vehicleRoutes(services)
            plantModelRoutes(services)
            eventRoutes(services, statusEvents)
            webSocketRoutes(services, options.webSocketBufferSize)
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
