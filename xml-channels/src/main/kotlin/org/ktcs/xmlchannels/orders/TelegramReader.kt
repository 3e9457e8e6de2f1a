package org.ktcs.xmlchannels.orders

import io.ktor.utils.io.ByteReadChannel
import io.ktor.utils.io.readAvailable
import java.io.ByteArrayOutputStream

/** Why a connection was closed without creating anything; [reason] goes into the log. */
internal class TelegramRejectedException(val reason: String) : Exception(reason)

/**
 * Reads one order telegram: up to the end of the stream (the client half-closed) or up to `\r\n\r\n`, whichever
 * comes first. The caller bounds the time the whole telegram may take.
 */
internal class TelegramReader(private val limit: Int) {
    suspend fun read(input: ByteReadChannel): ByteArray {
        val telegram = ByteArrayOutputStream()
        val buffer = ByteArray(BUFFER_SIZE)
        while (true) {
            val count = input.readAvailable(buffer, 0, buffer.size)
            if (count < 0) return telegram.toByteArray()
            val scanFrom = (telegram.size() - TERMINATOR.size + 1).coerceAtLeast(0)
            telegram.write(buffer, 0, count)
            if (telegram.size() > limit) throw TelegramRejectedException("telegram longer than $limit bytes")
            val bytes = telegram.toByteArray()
            val end = indexOfTerminator(bytes, scanFrom)
            if (end >= 0) return bytes.copyOf(end)
        }
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
