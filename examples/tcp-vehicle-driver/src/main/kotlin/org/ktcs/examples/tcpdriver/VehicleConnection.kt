package org.ktcs.examples.tcpdriver

import org.slf4j.LoggerFactory
import java.io.IOException
import java.net.InetSocketAddress
import java.net.Socket
import java.util.concurrent.LinkedBlockingQueue
import kotlin.concurrent.thread

/**
 * A TCP connection to one vehicle, kept open until [close]: connects (again after [reconnectDelayMillis] when it
 * fails or drops), hands every received line to [listener] on its own thread and writes the lines given to [send]
 * on another, so that the kernel context never waits for the network.
 */
class VehicleConnection(
    private val name: String,
    private val address: InetSocketAddress,
    private val listener: Listener,
    private val reconnectDelayMillis: Long = 500,
) {
    /** What happens on the connection; called on the connection's threads. */
    interface Listener {
        fun connected()

        fun received(line: String)

        fun disconnected(reason: String)
    }

    private val log = LoggerFactory.getLogger(VehicleConnection::class.java)
    private val outgoing = LinkedBlockingQueue<String>()

    @Volatile private var running = false

    // Each open() starts a session; a thread of an earlier one (closed, then opened again) ends instead of serving.
    @Volatile private var session = 0L

    @Volatile private var socket: Socket? = null
    private var connector: Thread? = null

    /** Whether a vehicle is connected right now. */
    val isConnected: Boolean get() = socket?.isConnected == true && socket?.isClosed == false

    fun open() {
        if (running) return
        running = true
        val mine = ++session
        connector = thread(name = "tcp-vehicle-$name", isDaemon = true) { connectWhileCurrent(mine) }
    }

    /** Queues [line] for the vehicle; lines still queued when a connection is made are dropped as stale. */
    fun send(line: String) {
        outgoing.put(line)
    }

    fun close() {
        running = false
        session++
        socket?.close()
        connector?.interrupt()
        connector = null
    }

    private fun isCurrent(mine: Long) = running && session == mine

    private fun connectWhileCurrent(mine: Long) {
        while (isCurrent(mine)) {
            try {
                Socket().use { connection ->
                    // Known before connecting, so that close() can abort a connection attempt.
                    socket = connection
                    connection.connect(address, CONNECT_TIMEOUT_MILLIS)
                    if (isCurrent(mine)) {
                        outgoing.clear()
                        serve(connection, mine)
                    }
                }
            } catch (error: IOException) {
                if (isCurrent(mine)) log.debug("vehicle {} at {}: {}", name, address, error.message)
            } finally {
                if (session == mine) socket = null
            }
            if (isCurrent(mine)) sleepBeforeReconnecting()
        }
    }

    private fun serve(connection: Socket, mine: Long) {
        listener.connected()
        val writer = thread(name = "tcp-vehicle-$name-writer", isDaemon = true) { write(connection) }
        var reason = "the vehicle closed the connection"
        try {
            connection.getInputStream().bufferedReader().lineSequence().forEach(listener::received)
        } catch (error: IOException) {
            reason = error.message ?: error.javaClass.simpleName
        } finally {
            writer.interrupt()
        }
        if (isCurrent(mine)) listener.disconnected(reason)
    }

    private fun write(connection: Socket) {
        val out = connection.getOutputStream().bufferedWriter()
        try {
            while (true) {
                out.write(outgoing.take())
                out.write("\n")
                if (outgoing.isEmpty()) out.flush()
            }
        } catch (_: InterruptedException) {
            // The connection ended.
        } catch (_: IOException) {
            connection.close()
        }
    }

    private fun sleepBeforeReconnecting() {
        try {
            Thread.sleep(reconnectDelayMillis)
        } catch (_: InterruptedException) {
            // close() was called.
        }
    }

    private companion object {
        const val CONNECT_TIMEOUT_MILLIS = 2_000
    }
}
