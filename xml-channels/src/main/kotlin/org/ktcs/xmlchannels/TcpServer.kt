package org.ktcs.xmlchannels

import io.ktor.network.selector.SelectorManager
import io.ktor.network.sockets.ServerSocket
import io.ktor.network.sockets.Socket
import io.ktor.network.sockets.aSocket
import io.ktor.network.sockets.awaitClosed
import io.ktor.network.sockets.openReadChannel
import io.ktor.network.sockets.openWriteChannel
import io.ktor.utils.io.ByteReadChannel
import io.ktor.utils.io.ByteWriteChannel
import io.ktor.utils.io.writeFully
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import org.slf4j.LoggerFactory
import java.io.IOException
import java.net.InetSocketAddress
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.atomic.AtomicLong
import java.net.ServerSocket as PlainServerSocket

/** One accepted connection: its channels and who it is, as the log names it. */
internal class Connection(private val socket: Socket) {
    val input: ByteReadChannel = socket.openReadChannel()
    val output: ByteWriteChannel = socket.openWriteChannel(autoFlush = false)
    val address: String = socket.remoteAddress.toString()

    fun close() = socket.close()
}

/**
 * A listening socket on non-blocking I/O: connections are coroutines, not threads, so a client that sends nothing
 * costs a few kilobytes. Each server has its own selector and scope, so a flood on one port never slows another.
 * At most [maxConnections] are served at once; a connection beyond that gets [refusal] and is closed.
 */
internal class TcpServer(
    private val name: String,
    bindAddress: String,
    port: Int,
    private val maxConnections: Int,
    private val refusal: ByteArray,
) : AutoCloseable {
    private val log = LoggerFactory.getLogger(TcpServer::class.java)
    private val selector = SelectorManager(Dispatchers.IO)
    private val scope = CoroutineScope(
        SupervisorJob() + Dispatchers.IO.limitedParallelism(WORKERS) + CoroutineName(name) +
            // Serving code turns every failure of a connection into a log line; this is the last safety net.
            CoroutineExceptionHandler { _, error -> log.error("{}: unexpected failure", name, error) },
    )
    private val server: ServerSocket = runBlocking {
        aSocket(selector).tcp().bind(bindAddress, port) {
            reuseAddress = true
            backlogSize = BACKLOG
        }
    }
    private val open = AtomicInteger()
    private val refusedSinceLog = AtomicLong()

    @Volatile
    private var lastRefusalLog = 0L

    /** The port actually bound (the configured one, or a free one for 0). */
    val port: Int = (server.localAddress as io.ktor.network.sockets.InetSocketAddress).port

    private val boundAddress = InetSocketAddress(bindAddress, this.port)

    /** How many connections are served now. */
    val connections: Int get() = open.get()

    fun start(serve: suspend (Connection) -> Unit) {
        scope.launch {
            while (true) {
                val socket = try {
                    server.accept()
                } catch (_: Exception) {
                    break // closed
                }
                scope.launch { serveOrRefuse(Connection(socket), serve) }
            }
        }
    }

    private suspend fun serveOrRefuse(connection: Connection, serve: suspend (Connection) -> Unit) {
        if (open.incrementAndGet() > maxConnections) {
            open.decrementAndGet()
            return refuse(connection)
        }
        try {
            serve(connection)
        } finally {
            open.decrementAndGet()
            connection.close()
        }
    }

    private suspend fun refuse(connection: Connection) {
        withTimeoutOrNull(REFUSAL_TIMEOUT_MILLIS) {
            runCatching {
                connection.output.writeFully(refusal)
                connection.output.flush()
            }
        }
        connection.close()
        logRefusal(connection.address)
    }

    /** One warning per few seconds, with a count, so that a flood cannot fill the log. */
    private fun logRefusal(address: String) {
        val refused = refusedSinceLog.incrementAndGet()
        val now = System.nanoTime()
        if (now - lastRefusalLog < REFUSAL_LOG_INTERVAL_NANOS && lastRefusalLog != 0L) return
        lastRefusalLog = now
        refusedSinceLog.addAndGet(-refused)
        log.warn(
            "{}: refused {} connection(s), the last from {}: {} connections are served already",
            name,
            refused,
            address,
            maxConnections,
        )
    }

    override fun close() {
        server.close()
        scope.cancel()
        runBlocking { withTimeoutOrNull(CLOSE_TIMEOUT_MILLIS) { server.awaitClosed() } }
        selector.close()
        awaitPortFree()
    }

    /**
     * A non-blocking listening socket registered with a selector keeps listening until the selector thread deregisters
     * it, after [close] has returned; a client connecting then would be accepted by nobody. Binding the port ourselves
     * succeeds only once it is free, so [close] returns when no connection to it can succeed any more.
     */
    private fun awaitPortFree() {
        val deadline = System.nanoTime() + CLOSE_TIMEOUT_MILLIS * 1_000_000
        while (!canBind(boundAddress) && System.nanoTime() < deadline) Thread.sleep(1)
    }

    private companion object {
        // Bursts of host connections (openTCS hosts open one per telegram) must not be refused by the OS.
        const val BACKLOG = 200

        // Parsing telegrams and rendering documents is all the CPU work here; I/O waits cost no thread.
        const val WORKERS = 4
        const val REFUSAL_TIMEOUT_MILLIS = 1_000L
        const val CLOSE_TIMEOUT_MILLIS = 2_000L
        const val REFUSAL_LOG_INTERVAL_NANOS = 5_000_000_000L
    }
}

/** Whether a listening socket could be bound to [address] now, i.e. nothing listens there. */
private fun canBind(address: InetSocketAddress): Boolean = try {
    PlainServerSocket().use {
        it.reuseAddress = true
        it.bind(address)
    }
    true
} catch (_: IOException) {
    false
}
