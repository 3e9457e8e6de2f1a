package org.ktcs.xmlchannels

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.launch
import java.net.InetSocketAddress
import java.net.ServerSocket
import java.net.Socket
import java.net.SocketException
import java.util.concurrent.ConcurrentHashMap

/**
 * A listening socket whose accept loop and connections run in [scope]: each connection in a coroutine of its own,
 * so that one that fails or blocks affects no other. Blocking socket I/O is fine there: the scope's dispatcher is
 * an elastic view of Dispatchers.IO. [close] closes the open connections too, which ends any blocked read or write.
 */
internal class TcpServer(private val scope: CoroutineScope, bindAddress: String, port: Int) : AutoCloseable {
    private val server = ServerSocket().apply {
        reuseAddress = true
        bind(InetSocketAddress(bindAddress, port), BACKLOG)
    }
    private val connections = ConcurrentHashMap.newKeySet<Socket>()

    /** The port actually bound (the configured one, or a free one for 0). */
    val port: Int get() = server.localPort

    fun start(serve: suspend (Socket) -> Unit) {
        scope.launch {
            while (true) {
                val socket = acceptOrNull() ?: break
                connections += socket
                // close() may have run between accept and add; then nobody else would close this one.
                if (server.isClosed) socket.close()
                scope.launch { serveAndClose(socket, serve) }
            }
        }
    }

    private suspend fun serveAndClose(socket: Socket, serve: suspend (Socket) -> Unit) {
        try {
            socket.use { serve(it) }
        } finally {
            connections -= socket
        }
    }

    private fun acceptOrNull(): Socket? = try {
        server.accept()
    } catch (error: SocketException) {
        if (server.isClosed) null else throw error
    }

    override fun close() {
        server.close()
        connections.forEach(Socket::close)
    }

    private companion object {
        // Bursts of host connections (openTCS hosts open one per telegram) must not be refused.
        const val BACKLOG = 200
    }
}
