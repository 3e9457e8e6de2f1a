package org.ktcs.kernel.web.plugins

import io.ktor.http.HttpStatusCode
import io.ktor.server.application.createApplicationPlugin
import io.ktor.server.application.hooks.ReceiveRequestBytes
import io.ktor.server.plugins.PayloadTooLargeException
import io.ktor.server.request.contentLength
import io.ktor.utils.io.ByteReadChannel
import io.ktor.utils.io.readAvailable
import io.ktor.utils.io.writeFully
import io.ktor.utils.io.writer
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers

/**
 * Refuses request bodies larger than [RequestSizeLimitConfig.maxBytes] (openTCS: servicewebapi.maxRequestBodySize,
 * 200 MB) with 413, so one client cannot fill the kernel's memory: at once when `Content-Length` says so, and while
 * reading a body without one (chunked) as soon as it passes the limit.
 */
val RequestSizeLimit = createApplicationPlugin("RequestSizeLimit", ::RequestSizeLimitConfig) {
    val limit = pluginConfig.maxBytes
    onCall { call ->
        val length = call.request.contentLength() ?: return@onCall
        if (length > limit) {
            call.respondErrors(
                HttpStatusCode.PayloadTooLarge,
                "request body of $length bytes is larger than the limit of $limit bytes",
            )
        }
    }
    on(ReceiveRequestBytes) { call, body ->
        if (call.request.contentLength() != null) body else limited(call, body, limit)
    }
}

class RequestSizeLimitConfig {
    var maxBytes: Long = 200L * 1024 * 1024
}

/** [body] passed on until it exceeds [limit] bytes; then reading it fails with [PayloadTooLargeException]. */
private fun limited(scope: CoroutineScope, body: ByteReadChannel, limit: Long): ByteReadChannel =
    scope.writer(Dispatchers.Unconfined) {
        val buffer = ByteArray(BUFFER_SIZE)
        var total = 0L
        while (true) {
            val count = body.readAvailable(buffer, 0, buffer.size)
            if (count < 0) break
            total += count
            if (total > limit) throw PayloadTooLargeException(limit)
            channel.writeFully(buffer, 0, count)
        }
    }.channel

private const val BUFFER_SIZE = 8 * 1024
