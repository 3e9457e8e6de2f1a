package org.ktcs.xmlchannels

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import java.net.InetAddress
import java.net.Socket
import java.net.SocketException

/** A host system's side of the order channel, as a test drives it. */
object HostClient {
    /**
     * Sends [telegram], then half-closes (or, with [crlfEnd], sends `\r\n\r\n` instead) and returns everything the
     * channel answers until it closes the connection; nothing if it resets the connection, as it may when it stops
     * reading a telegram that is too long.
     */
    suspend fun send(port: Int, telegram: ByteArray, crlfEnd: Boolean = false): String = withContext(Dispatchers.IO) {
        connect(port).use { socket ->
            try {
                socket.getOutputStream().write(telegram)
                if (crlfEnd) socket.getOutputStream().write("\r\n\r\n".toByteArray()) else socket.shutdownOutput()
                socket.getInputStream().readBytes().toString(Charsets.UTF_8)
            } catch (_: SocketException) {
                ""
            }
        }
    }

    suspend fun send(port: Int, telegram: String, crlfEnd: Boolean = false) =
        send(port, telegram.toByteArray(Charsets.UTF_8), crlfEnd)

    fun connect(port: Int) = Socket(InetAddress.getLoopbackAddress(), port).apply { soTimeout = TIMEOUT_MILLIS }

    private const val TIMEOUT_MILLIS = 10_000
}
