package org.ktcs.xmlchannels.status

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import java.io.ByteArrayOutputStream
import java.io.IOException
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket

/** A host system's side of the status channel: reads the messages up to each separator `|`. */
class StatusClientSocket(port: Int, receiveBuffer: Int? = null) : AutoCloseable {
    val socket = Socket().apply {
        receiveBuffer?.let { receiveBufferSize = it }
        soTimeout = 10_000
        connect(InetSocketAddress(InetAddress.getLoopbackAddress(), port))
    }
    private val input = socket.getInputStream().buffered()

    /** The next message without its separator, or `null` once the channel closed or reset the connection. */
    suspend fun next(): String? = withContext(Dispatchers.IO) {
        val message = ByteArrayOutputStream()
        var byte = readOrEnd()
        while (byte >= 0 && byte != '|'.code) {
            message.write(byte)
            byte = readOrEnd()
        }
        if (byte < 0) null else message.toString(Charsets.UTF_8)
    }

    private fun readOrEnd(): Int = try {
        input.read()
    } catch (_: IOException) {
        -1
    }

    override fun close() = socket.close()
}
