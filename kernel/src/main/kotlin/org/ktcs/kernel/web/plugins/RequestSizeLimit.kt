package org.ktcs.kernel.web.plugins

import io.ktor.http.HttpStatusCode
import io.ktor.server.application.createApplicationPlugin
import io.ktor.server.request.contentLength

/**
 * Refuses request bodies larger than [RequestSizeLimitConfig.maxBytes] (openTCS: servicewebapi.maxRequestBodySize,
 * 200 MB) with 413 before reading them, so one client cannot fill the kernel's memory.
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
}

class RequestSizeLimitConfig {
    var maxBytes: Long = 200L * 1024 * 1024
}
