package org.ktcs.adapters.vda5050

import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.concurrent.thread

/**
 * A TCP relay in front of the broker: what a test uses to cut a vehicle's connection without a DISCONNECT, as a
 * vehicle that drives out of Wi-Fi range does, so the broker publishes its last will.
 */
class TcpRelay(private val targetPort: Int) : AutoCloseable {
    private val server = ServerSocket(0, 50, InetAddress.getLoopbackAddress())
    private val sockets = CopyOnWriteArrayList<Socket>()
    val port: Int get() = server.localPort

    @Volatile var accepting = true

    init {
        thread(isDaemon = true, name = "relay-$port") {
            while (!server.isClosed) {
                val client = runCatching { server.accept() }.getOrNull() ?: break
                if (!accepting) {
                    client.close()
                    continue
                }
                val upstream = runCatching { Socket(InetAddress.getLoopbackAddress(), targetPort) }.getOrNull()
                if (upstream == null) {
                    client.close()
                    continue
                }
                sockets += client
                sockets += upstream
                pump(client, upstream)
                pump(upstream, client)
            }
        }
    }

    /** Drops every connection through the relay; new ones are refused until [accepting] is set again. */
    fun cut() {
        accepting = false
        sockets.forEach { runCatching { it.close() } }
        sockets.clear()
    }

    private fun pump(from: Socket, to: Socket) = thread(isDaemon = true) {
        runCatching { from.getInputStream().transferTo(to.getOutputStream()) }
        runCatching { from.close() }
        runCatching { to.close() }
    }

    override fun close() {
        cut()
        server.close()
    }
}
