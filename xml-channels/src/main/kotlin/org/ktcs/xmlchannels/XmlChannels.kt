package org.ktcs.xmlchannels

import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import org.ktcs.api.service.KernelServices
import org.ktcs.xmlchannels.orders.OrderChannelServer
import org.ktcs.xmlchannels.orders.ScriptFiles
import org.ktcs.xmlchannels.status.StatusChannelServer
import org.ktcs.xmlchannels.status.StatusMessages
import org.slf4j.LoggerFactory
import java.time.Clock
import java.util.concurrent.CopyOnWriteArrayList

/**
 * The XML order and status channels, openTCS 4.x's TCP host interface. [start] listens on both ports, [close]
 * stops listening and drops every connection. Each channel listens on non-blocking I/O in a scope of its own (see
 * [TcpServer]), off the kernel context, so that neither can silence the other; the kernel is reached only through
 * [KernelServices].
 */
class XmlChannels(
    private val services: KernelServices,
    private val settings: XmlChannelSettings,
    private val clock: Clock = Clock.systemDefaultZone(),
) : AutoCloseable {
    private val log = LoggerFactory.getLogger(XmlChannels::class.java)
    private val scope = CoroutineScope(
        SupervisorJob() + Dispatchers.Default + CoroutineName("xml-channels") +
            CoroutineExceptionHandler { _, error -> log.error("XML channels: unexpected failure", error) },
    )
    private val servers = CopyOnWriteArrayList<TcpServer>()
    private val statusChannel = StatusChannelServer(
        StatusMessages(clock, settings.statusSeparator),
        settings.statusBufferSize,
        scope,
    ) { services.eventsAfter {}.second }

    /** The bound order channel port, once started. */
    var ordersPort: Int = -1
        private set

    /** The bound status channel port, once started. */
    var statusPort: Int = -1
        private set

    /** Status channel clients connected now (for tests). */
    internal val statusClients get() = statusChannel.clientCount

    /** Listens on both ports; if either can't be bound, nothing stays open. */
    fun start(): XmlChannels = apply {
        try {
            ScriptFiles(settings.scriptsDirectory).writeTemplate()
            val orderChannel = OrderChannelServer(services.transportOrders, settings)
            ordersPort =
                listen("XML order channel", settings.ordersPort, settings.ordersMaxConnections, orderChannel::serve)
            statusPort =
                listen("XML status channel", settings.statusPort, settings.statusMaxConnections, statusChannel::serve)
        } catch (error: Exception) {
            close()
            throw error
        }
        log.info("XML channels: orders on port {}, status on port {}", ordersPort, statusPort)
    }

    private fun listen(name: String, port: Int, limit: Int, serve: suspend (Connection) -> Unit): Int {
        val refusal = "kTCS: too many connections to the $name (limit $limit); try again later\r\n"
        val server = TcpServer(name, settings.bindAddress, port, limit, refusal.toByteArray(Charsets.UTF_8))
        servers += server
        server.start(serve)
        return server.port
    }

    override fun close() {
        servers.forEach(TcpServer::close)
        scope.cancel()
    }
}
