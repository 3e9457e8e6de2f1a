package org.ktcs.kernel.web.plugins

import io.ktor.http.HttpHeaders
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.ApplicationCall
import io.ktor.server.application.createRouteScopedPlugin
import kotlinx.coroutines.delay

/**
 * openTCS's optional access key: with a key configured, every request must carry it in `X-Api-Access-Key`, or it is
 * answered 403 after a short delay (as openTCS does, to slow down guessing). Browsers cannot set headers on a
 * WebSocket, so a WebSocket upgrade may carry the key in the query parameter `accessKey` instead.
 */
val AccessKey = createRouteScopedPlugin("AccessKey", ::AccessKeyConfig) {
    val key = pluginConfig.key
    onCall { call ->
        if (key.isNotEmpty() && call.sentKey() != key) {
            delay(pluginConfig.refusalDelayMillis)
            call.respondErrors(HttpStatusCode.Forbidden, "missing or wrong $HEADER header")
        }
    }
}

class AccessKeyConfig {
    /** The key; empty means no key is needed. */
    var key: String = ""
    var refusalDelayMillis: Long = 2_000
}

const val HEADER = "X-Api-Access-Key"

private fun ApplicationCall.sentKey(): String? = request.headers[HEADER]
    ?: request.queryParameters["accessKey"].takeIf {
        request.headers[HttpHeaders.Upgrade].equals("websocket", ignoreCase = true)
    }
