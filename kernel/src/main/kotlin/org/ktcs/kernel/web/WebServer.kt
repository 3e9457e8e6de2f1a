package org.ktcs.kernel.web

import io.ktor.serialization.kotlinx.json.json
import io.ktor.server.application.Application
import io.ktor.server.application.ApplicationStopPreparing
import io.ktor.server.application.install
import io.ktor.server.cio.CIO
import io.ktor.server.engine.EmbeddedServer
import io.ktor.server.engine.connector
import io.ktor.server.engine.embeddedServer
import io.ktor.server.engine.sslConnector
import io.ktor.server.netty.Netty
import io.ktor.server.netty.NettyApplicationEngine
import io.ktor.server.plugins.contentnegotiation.ContentNegotiation
import io.ktor.server.response.respond
import io.ktor.server.routing.post
import io.ktor.server.routing.route
import io.ktor.server.routing.routing
import io.ktor.server.websocket.WebSockets
import io.netty.buffer.UnpooledByteBufAllocator
import io.netty.channel.ChannelOption
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import org.ktcs.api.service.KernelServices
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.web.WebContribution
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.config.WebEngine
import org.ktcs.kernel.events.SubscriberTooSlowException
import org.ktcs.kernel.web.docs.ApiDocument
import org.ktcs.kernel.web.docs.docsRoutes
import org.ktcs.kernel.web.docs.openApiRoutes
import org.ktcs.kernel.web.plugins.AccessKey
import org.ktcs.kernel.web.plugins.Cors
import org.ktcs.kernel.web.plugins.CrossSiteGuard
import org.ktcs.kernel.web.plugins.RequestSizeLimit
import org.ktcs.kernel.web.plugins.installErrorResponses
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.dispatcherTrigger
import org.ktcs.kernel.web.v1.drivers.driverPanelRoutes
import org.ktcs.kernel.web.v1.events.StatusEventBuffer
import org.ktcs.kernel.web.v1.events.eventRoutes
import org.ktcs.kernel.web.v1.orders.orderSequenceRoutes
import org.ktcs.kernel.web.v1.orders.transportOrderRoutes
import org.ktcs.kernel.web.v1.plantmodel.plantModelFileRoutes
import org.ktcs.kernel.web.v1.plantmodel.plantModelRoutes
import org.ktcs.kernel.web.v1.vehicles.vehicleRoutes
import org.ktcs.kernel.web.ws.LiveWebSockets
import org.ktcs.kernel.web.ws.webSocketRoutes
import org.slf4j.LoggerFactory
import java.net.BindException
import java.net.InetSocketAddress
import java.net.ServerSocket

/** What the web API's plugins are set to (from the `web.*` settings). */
data class WebOptions(
    val accessKey: String = "",
    val allowedOrigins: String = "",
    val maxRequestBodyBytes: Long = 200L * 1024 * 1024,
    val webSocketBufferSize: Int = 1000,
    val allowLocalShutdown: Boolean = false,
)

/** WebSocket clients only send small control messages; a larger frame closes the connection with 1009. */
const val MAX_WEBSOCKET_FRAME_BYTES = 64L * 1024

/** Asks the application to shut down, as `DELETE /v1/kernel` does. */
fun interface ShutdownRequest {
    fun request()
}

/**
 * The HTTP(S) server of the kernel application: Ktor on Netty, or on Ktor's CIO engine with `web.engine=CIO` (plain
 * HTTP only). Netty spends about a third of CIO's CPU per request and answers sooner (README, "Performance").
 */
class WebServer(
    private val config: KtcsConfig,
    private val version: KernelVersion,
    private val services: KernelServices,
    private val shutdown: ShutdownRequest,
    private val contributions: List<WebContribution> = emptyList(),
    private val eventTap: KernelEventTap? = null,
) {
    private var server: EmbeddedServer<*, *>? = null

    /**
     * Starts listening and returns the base URL it serves, with the port actually bound: HTTPS when `web.tls.*` is
     * set (always on Netty: CIO cannot serve TLS), else plain HTTP on the engine `web.engine` names.
     */
    fun start(): String {
        val host = config[KtcsSettings.webBindAddress]
        val port = config[KtcsSettings.webPort]
        val options = WebOptions(
            accessKey = config[KtcsSettings.webAccessKey],
            allowedOrigins = config[KtcsSettings.webAllowedOrigins],
            maxRequestBodyBytes = config[KtcsSettings.webMaxRequestBodySize] * 1024 * 1024,
            webSocketBufferSize = config[KtcsSettings.webSocketBufferSize],
            allowLocalShutdown = config[KtcsSettings.webAllowLocalShutdown],
        )
        checkPortFree(host, port)
        val module: Application.() -> Unit = {
            webModule(version, services, options, shutdown, contributions, eventTap)
        }
        val tls = WebTls.from(config)
        val engine = config[KtcsSettings.webEngine]
        val started = if (tls == null && engine == WebEngine.CIO) {
            embeddedServer(CIO, port = port, host = host, module = module)
        } else {
            embeddedServer(Netty, configure = {
                sizedForFewCores()
                if (tls == null) {
                    connector {
                        this.host = host
                        this.port = port
                    }
                } else {
                    sslConnector(tls.keyStore, tls.alias, { tls.password }, { tls.password }) {
                        this.host = host
                        this.port = port
                    }
                }
            }, module = module)
        }.start(wait = false)
        server = started
        val bound = runBlocking { started.engine.resolvedConnectors().first().port }
        return "${if (tls == null) "http" else "https"}://$host:$bound"
    }

    /**
     * Ktor's engine binds in a coroutine, so a port in use would surface as an uncaught stack trace without the
     * port; trying the address first gives the user one line that names it.
     */
    private fun checkPortFree(host: String, port: Int) {
        if (port == 0) return
        try {
            ServerSocket().use { socket ->
                socket.reuseAddress = true
                socket.bind(InetSocketAddress(host, port))
            }
        } catch (e: BindException) {
            throw BindException(
                "web API port $port on $host is already in use (${e.message}); set web.port to a free port",
            )
        }
    }

    fun stop() {
        server?.stop(gracePeriodMillis = 200, timeoutMillis = 2_000)
        server = null
    }
}

/**
 * One event loop per core does the I/O and runs the handlers (a request is read, handled and answered on the loop of
 * its connection, without handing it to another thread pool), and one accepts connections. Buffers are not pooled:
 * a request and its answer are small, and a pool's arenas cost resident memory an idle kTCS would keep.
 */
private fun NettyApplicationEngine.Configuration.sizedForFewCores() {
    connectionGroupSize = 1
    workerGroupSize = Runtime.getRuntime().availableProcessors()
    callGroupSize = workerGroupSize
    shareWorkGroup = true
    configureBootstrap = { childOption(ChannelOption.ALLOCATOR, UnpooledByteBufAllocator.DEFAULT) }
}

/**
 * Installs the plugins and mounts the routes; also used by tests with Ktor's test host. [eventTap] fills the buffer
 * of `GET /v1/events` in the kernel context; without it (tests) a subscription to [services]' events does.
 */
fun Application.webModule(
    version: KernelVersion,
    services: KernelServices,
    options: WebOptions = WebOptions(),
    shutdown: ShutdownRequest = ShutdownRequest {},
    contributions: List<WebContribution> = emptyList(),
    eventTap: KernelEventTap? = null,
) {
    install(ContentNegotiation) { json(V1Json.json) }
    installErrorResponses()
    install(Cors) { allowedOrigins = options.allowedOrigins }
    install(RequestSizeLimit) { maxBytes = options.maxRequestBodyBytes }
    install(WebSockets) { maxFrameSize = MAX_WEBSOCKET_FRAME_BYTES }
    val statusEvents = StatusEventBuffer()
    if (eventTap != null) eventTap.listen(statusEvents::add) else launch { feed(statusEvents, services) }
    val webSockets = LiveWebSockets()
    monitor.subscribe(ApplicationStopPreparing) { webSockets.closeAll() }
    val document = lazy { ApiDocument.current }
    routing {
        contributions.forEach { it.install(this) }
        docsRoutes(document)
        route("/v1") {
            install(AccessKey) { key = options.accessKey }
            install(CrossSiteGuard) { allowedOrigins = options.allowedOrigins }
            openApiRoutes(document)
            kernelRoutes(version, shutdown, options)
            transportOrderRoutes(services)
            orderSequenceRoutes(services)
            vehicleRoutes(services)
            driverPanelRoutes(services)
            plantModelRoutes(services)
            plantModelFileRoutes()
            eventRoutes(services, statusEvents)
            webSocketRoutes(services, options.webSocketBufferSize, webSockets)
            dispatcherTrigger(services)
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
