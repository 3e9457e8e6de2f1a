package org.ktcs.kernel.web.v1.orders

import io.ktor.http.ContentType
import io.ktor.http.content.OutgoingContent
import io.ktor.http.withCharset
import io.ktor.utils.io.ByteWriteChannel
import io.ktor.utils.io.writeByte
import io.ktor.utils.io.writeFully

/**
 * A JSON array of elements that are encoded already, written to the connection one element after another. A list of
 * thousands of orders is several megabytes; copying it into one array per request left that much garbage behind
 * every request (and the collections it caused set the list's p95 latency).
 */
class JsonArrayContent(private val elements: List<ByteArray>) : OutgoingContent.WriteChannelContent() {
    override val contentType: ContentType = JSON_UTF8

    override val contentLength: Long = elements.sumOf { it.size.toLong() } + (elements.size - 1).coerceAtLeast(0) + 2

    override suspend fun writeTo(channel: ByteWriteChannel) {
        channel.writeByte(OPEN)
        elements.forEachIndexed { index, element ->
            if (index > 0) channel.writeByte(COMMA)
            channel.writeFully(element)
        }
        channel.writeByte(CLOSE)
    }

    /** The whole array in one buffer, as [writeTo] writes it. */
    fun toByteArray(): ByteArray {
        val out = ByteArray(contentLength.toInt())
        var at = 0
        out[at++] = OPEN
        elements.forEachIndexed { index, element ->
            if (index > 0) out[at++] = COMMA
            element.copyInto(out, at)
            at += element.size
        }
        out[at] = CLOSE
        return out
    }

    private companion object {
        const val OPEN = '['.code.toByte()
        const val COMMA = ','.code.toByte()
        const val CLOSE = ']'.code.toByte()
    }
}

/** `application/json; charset=UTF-8`, the content type of every order response. */
internal val JSON_UTF8 = ContentType.Application.Json.withCharset(Charsets.UTF_8)
