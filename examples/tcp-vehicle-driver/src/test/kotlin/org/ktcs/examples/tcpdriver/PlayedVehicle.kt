package org.ktcs.examples.tcpdriver

import java.io.BufferedReader
import java.io.BufferedWriter
import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.net.SocketTimeoutException

/** The test's side of the line protocol: a vehicle that waits for the driver to connect. */
class PlayedVehicle : AutoCloseable {
    private val server = ServerSocket(0, 1, InetAddress.getLoopbackAddress())
    private var socket: Socket? = null
    val port: Int get() = server.localPort

    private var reader: BufferedReader? = null
    private var writer: BufferedWriter? = null

    /** Waits for the driver to connect and returns the first line it sends. */
    fun awaitDriver(): String {
        server.soTimeout = TIMEOUT_MILLIS
        val accepted = server.accept().also { it.soTimeout = TIMEOUT_MILLIS }
        socket = accepted
        reader = accepted.getInputStream().bufferedReader()
        writer = accepted.getOutputStream().bufferedWriter()
        return receive()
    }

    /** Drops the connection, as a vehicle out of radio range does. */
    fun dropConnection() {
        socket?.close()
    }

    private val connection get() = checkNotNull(socket) { "the driver has not connected" }

    fun send(vararg lines: String) {
        val out = checkNotNull(writer) { "the driver has not connected" }
        lines.forEach { out.write(it + "\n") }
        out.flush()
    }

    fun receive(): String =
        checkNotNull(reader) { "the driver has not connected" }.readLine() ?: error("the driver closed the connection")

    /** The next line if one arrives within [millis], else `null`. */
    fun receiveWithin(millis: Int): String? {
        connection.soTimeout = millis
        return try {
            checkNotNull(reader).readLine()
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
