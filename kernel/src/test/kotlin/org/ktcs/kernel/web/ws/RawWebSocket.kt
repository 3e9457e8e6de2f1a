package org.ktcs.kernel.web.ws

import java.io.BufferedInputStream
import java.io.ByteArrayOutputStream
import java.io.DataInputStream
import java.net.InetSocketAddress
import java.net.Socket
import java.net.SocketTimeoutException
import java.net.URI
import kotlin.random.Random

/**
 * A minimal WebSocket client on a plain socket with a small receive buffer, so that a test can stop reading and the
 * server really feels it (the JDK's client keeps reading into its own buffers).
 */
class RawWebSocket(uri: URI) : AutoCloseable {
    private val socket = Socket().apply {
        receiveBufferSize = 4096
        soTimeout = 30_000
        connect(InetSocketAddress(uri.host, uri.port))
    }
    private val input = DataInputStream(BufferedInputStream(socket.getInputStream()))
    private val output = socket.getOutputStream()

    init {
        val request = "GET ${uri.path} HTTP/1.1\r\nHost: ${uri.host}:${uri.port}\r\nUpgrade: websocket\r\n" +
            "Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
        output.write(request.toByteArray())
        val status = readLine()
        check(" 101 " in status) { "no WebSocket upgrade: $status" }
        while (readLine().isNotEmpty()) Unit
    }

    /** Sends [text] as one masked text frame, as a client must. */
    fun sendText(text: String) {
        val payload = text.toByteArray()
        val mask = Random.nextBytes(4)
        val frame = ByteArrayOutputStream()
        frame.write(0x81)
        when {
            payload.size < 126 -> frame.write(0x80 or payload.size)

            payload.size < 65_536 -> frame.write(0x80 or 126).also {
                frame.write(payload.size shr 8)
                frame.write(payload.size and 0xff)
            }

            else -> error("test messages are short")
        }
        frame.write(mask)
        payload.forEachIndexed { i, byte -> frame.write(byte.toInt() xor mask[i % 4].toInt()) }
        output.write(frame.toByteArray())
    }

    /** The next text message, reassembled from its frames; control frames are skipped. */
    fun receiveText(): String {
        val message = ByteArrayOutputStream()
        while (true) {
            val first = input.readUnsignedByte()
            val length = when (val short = input.readUnsignedByte() and 0x7f) {
                126 -> input.readUnsignedShort().toLong()
                127 -> input.readLong()
                else -> short.toLong()
            }
            val payload = ByteArray(length.toInt()).also(input::readFully)
            val opcode = first and 0x0f
            if (opcode >= CONTROL_FRAMES) continue
            message.write(payload)
            if (first and FIN != 0) return message.toString(Charsets.UTF_8)
        }
    }

    /** The next text message, or `null` if none begins within [quietMillis]. */
    fun receiveTextOrNull(quietMillis: Int): String? {
        socket.soTimeout = quietMillis
        return try {
            receiveText()
        } catch (quiet: SocketTimeoutException) {
            null
        } finally {
            socket.soTimeout = 30_000
        }
    }

    override fun close() = socket.close()

    private fun readLine(): String = buildString {
        while (true) {
            val char = input.readUnsignedByte().toChar()
            if (char == '\n') break
            if (char != '\r') append(char)
        }
    }

    private companion object {
        const val FIN = 0x80
        const val CONTROL_FRAMES = 0x8
    }
}
