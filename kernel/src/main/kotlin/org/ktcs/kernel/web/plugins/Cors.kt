package org.ktcs.kernel.web.plugins

import io.ktor.http.HttpHeaders
import io.ktor.http.HttpMethod
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.createApplicationPlugin
import io.ktor.server.response.header
import io.ktor.server.response.respond

/**
 * Cross-origin access for browser clients served from elsewhere, as openTCS's web API allows it
 * (`Access-Control-Allow-Origin: *` there). Answers preflight requests itself.
 */
val Cors = createApplicationPlugin("Cors", ::CorsConfig) {
    val origins = pluginConfig.allowedOrigins
    onCall { call ->
        if (origins.isEmpty()) return@onCall
        call.response.header(HttpHeaders.AccessControlAllowOrigin, origins)
        if (call.request.local.method == HttpMethod.Options) {
            call.response.header(HttpHeaders.AccessControlAllowMethods, "GET, POST, PUT, DELETE, OPTIONS")
            call.response.header(HttpHeaders.AccessControlAllowHeaders, "Content-Type, $HEADER")
            call.respond(HttpStatusCode.OK)
        }
    }
}

class CorsConfig {
    /** The value of `Access-Control-Allow-Origin`; empty: no cross-origin access. */
    var allowedOrigins: String = "*"
}
