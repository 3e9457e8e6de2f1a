package org.ktcs.kernel.web.plugins

import io.ktor.http.HttpHeaders
import io.ktor.http.HttpMethod
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.ApplicationCall
import io.ktor.server.application.createApplicationPlugin
import io.ktor.server.response.header
import io.ktor.server.response.respond

/**
 * Cross-origin access for browser clients served from elsewhere. By default there is none: the overview and the docs
 * come from kTCS's own origin and need no CORS. `web.allowedOrigins` lists the origins (comma-separated, or `*` as
 * in openTCS) whose pages may call the API; kTCS answers their preflight requests itself.
 */
val Cors = createApplicationPlugin("Cors", ::CorsConfig) {
    val origins = BrowserOrigins(pluginConfig.allowedOrigins)
    onCall { call ->
        val origin = call.request.headers[HttpHeaders.Origin] ?: return@onCall
        call.response.header(HttpHeaders.Vary, HttpHeaders.Origin)
        val allowed = origins.allowsCrossOrigin(origin)
        if (allowed) call.response.header(HttpHeaders.AccessControlAllowOrigin, origins.headerValue(origin))
        if (call.request.local.method != HttpMethod.Options) return@onCall
        if (!allowed) {
            return@onCall call.respondErrors(HttpStatusCode.Forbidden, "origin '$origin' is not in web.allowedOrigins")
        }
        call.response.header(HttpHeaders.AccessControlAllowMethods, "GET, POST, PUT, DELETE, OPTIONS")
        call.response.header(HttpHeaders.AccessControlAllowHeaders, "Content-Type, $HEADER, $CLIENT_HEADER")
        call.respond(HttpStatusCode.OK)
    }
}

class CorsConfig {
    /** `web.allowedOrigins`: empty for none, `*` for any, else a comma-separated list of origins. */
    var allowedOrigins: String = ""
}

/** Which browser origins may use the API: kTCS's own always, others as `web.allowedOrigins` lists them. */
class BrowserOrigins(setting: String) {
    private val any = setting.trim() == "*"
    private val listed = setting.split(',').map {
        it.trim().trimEnd('/')
    }.filter { it.isNotEmpty() && it != "*" }.toSet()

    fun allowsCrossOrigin(origin: String): Boolean = any || origin.trimEnd('/') in listed

    fun headerValue(origin: String): String = if (any) "*" else origin

    /** Whether a page from [origin] may use kTCS as [call] reaches it: its own origin, or an allowed one. */
    fun allows(origin: String, call: ApplicationCall): Boolean = isSameOrigin(origin, call) || allowsCrossOrigin(origin)

    private fun isSameOrigin(origin: String, call: ApplicationCall): Boolean {
        val host = call.request.headers[HttpHeaders.Host] ?: return false
        return origin == "http://$host" || origin == "https://$host"
    }
}
