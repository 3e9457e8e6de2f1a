package org.ktcs.xmlchannels.orders

import java.io.ByteArrayOutputStream
import java.io.InputStream
import java.net.SocketTimeoutException

/** Why a connection was closed without creating anything; [reason] goes into the log. */
internal class TelegramRejectedException(val reason: String) : Exception(reason)

/**
 * Reads one order telegram: up to the end of the stream (the client half-closed) or up to `\r\n\r\n`, whichever
 * comes first. The stream's read timeout is the idle timeout.
 */
internal class TelegramReader(private val limit: Int) {
    fun read(input: InputStream): ByteArray {
        val telegram = ByteArrayOutputStream()
        val buffer = ByteArray(BUFFER_SIZE)
        while (true) {
            val count = readOrTimeOut(input, buffer)
            if (count < 0) return telegram.toByteArray()
            val scanFrom = (telegram.size() - TERMINATOR.size + 1).coerceAtLeast(0)
            telegram.write(buffer, 0, count)
            if (telegram.size() > limit) throw TelegramRejectedException("telegram longer than $limit bytes")
            val bytes = telegram.toByteArray()
            val end = indexOfTerminator(bytes, scanFrom)
            if (end >= 0) return bytes.copyOf(end)
        }
    }

    private fun readOrTimeOut(input: InputStream, buffer: ByteArray): Int = try {
        input.read(buffer)
    } catch (_: SocketTimeoutException) {
        throw TelegramRejectedException("no data within the idle timeout")
    }

    private fun indexOfTerminator(bytes: ByteArray, from: Int): Int =
        (from..bytes.size - TERMINATOR.size).firstOrNull { start ->
            TERMINATOR.indices.all { bytes[start + it] == TERMINATOR[it] }
        } ?: -1

    private companion object {
        const val BUFFER_SIZE = 16 * 1024
        val TERMINATOR = "\r\n\r\n".toByteArray()
    }
}
