package org.ktcs.examples.tcpdriver

import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.net.SocketTimeoutException

/** The test's side of the line protocol: a vehicle that waits for the driver to connect. */
class PlayedVehicle : AutoCloseable {
    private val server = ServerSocket(0, 1, InetAddress.getLoopbackAddress())
    private var socket: Socket? = null
    val port: Int get() = server.localPort

    fun awaitDriver() {
        server.soTimeout = TIMEOUT_MILLIS
        socket = server.accept().also { it.soTimeout = TIMEOUT_MILLIS }
    }

    private val connection get() = checkNotNull(socket) { "the driver has not connected" }
    private val reader by lazy { connection.getInputStream().bufferedReader() }
    private val writer by lazy { connection.getOutputStream().bufferedWriter() }

    fun send(vararg lines: String) {
        lines.forEach { writer.write(it + "\n") }
        writer.flush()
    }

    fun receive(): String = reader.readLine() ?: error("the driver closed the connection")

    /** The next line if one arrives within [millis], else `null`. */
    fun receiveWithin(millis: Int): String? {
        connection.soTimeout = millis
        return try {
            reader.readLine()
        } catch (_: SocketTimeoutException) {
            null
        } finally {
            connection.soTimeout = TIMEOUT_MILLIS
        }
    }

    override fun close() {
        socket?.close()
        server.close()
    }

    private companion object {
        const val TIMEOUT_MILLIS = 20_000
    }
}
