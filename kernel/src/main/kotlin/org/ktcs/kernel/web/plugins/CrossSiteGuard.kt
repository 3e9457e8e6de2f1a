package org.ktcs.kernel.web.plugins

import io.ktor.http.ContentType
import io.ktor.http.HttpHeaders
import io.ktor.http.HttpMethod
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.ApplicationCall
import io.ktor.server.application.createRouteScopedPlugin
import java.nio.charset.Charset

/** A header any client may set to say "I am a program, not a form": browsers must ask (preflight) before sending it. */
const val CLIENT_HEADER = "X-Requested-With"

/**
 * Keeps web pages from changing kTCS (cross-site request forgery): a page may send a "simple" request (a form, or
 * `fetch` with a `text/plain` body) anywhere without asking, so every request that changes something must have a
 * JSON body or a header such a request cannot carry ([CLIENT_HEADER] or the access key). A request a browser sends
 * (it has an `Origin`) must also come from kTCS's own pages or an allowed origin; so must a WebSocket upgrade, which
 * browsers send from any page without asking.
 *
 * Programs (curl, openTCS clients) send no `Origin` and are unaffected unless they send a body that is not JSON.
 */
val CrossSiteGuard = createRouteScopedPlugin("CrossSiteGuard", ::CrossSiteGuardConfig) {
    val origins = BrowserOrigins(pluginConfig.allowedOrigins)
    onCall { call ->
        if (call.request.headers[HttpHeaders.Upgrade].equals("websocket", ignoreCase = true)) {
            val origin = call.request.headers[HttpHeaders.Origin] ?: return@onCall
            if (!origins.allows(origin, call)) {
                call.respondErrors(
                    HttpStatusCode.Forbidden,
                    "WebSocket connections from pages of origin '$origin' are refused",
                )
            }
            return@onCall
        }
        if (call.request.local.method !in CHANGING) return@onCall
        refusal(call, origins)?.let { (status, message) -> call.respondErrors(status, message) }
    }
}

class CrossSiteGuardConfig {
    var allowedOrigins: String = ""
}

private val CHANGING = setOf(HttpMethod.Post, HttpMethod.Put, HttpMethod.Delete, HttpMethod.Patch)

private typealias Refusal = Pair<HttpStatusCode, String>

private fun refusal(call: ApplicationCall, origins: BrowserOrigins): Refusal? {
    val header = call.request.headers[HttpHeaders.ContentType]
    val type = header?.let { runCatching { ContentType.parse(it) }.getOrNull() }
    return contentRefusal(header, type) ?: originRefusal(call, origins, hasBody = type != null)
}

/**
 * A body must be JSON in a charset the JVM knows, or XML (a plant-model file for `POST /v1/plantModel/fromFile`):
 * browsers ask before sending either from another page, unlike `text/plain` or a form.
 */
private fun contentRefusal(header: String?, type: ContentType?): Refusal? {
    if (header == null) return null
    if (type == null) {
        return HttpStatusCode.UnsupportedMediaType to "malformed Content-Type '$header'; send application/json"
    }
    val charset = type.parameter("charset")
    if (charset != null && runCatching { Charset.isSupported(charset) }.getOrDefault(false).not()) {
        return HttpStatusCode.UnsupportedMediaType to "unknown charset '$charset'; send UTF-8"
    }
    if (type.match(ContentType.Application.Json) || type.match(ContentType.Application.Xml)) return null
    return HttpStatusCode.UnsupportedMediaType to
        "request bodies must be JSON (Content-Type: application/json), not '${type.withoutParameters()}'"
}

/** A browser's request must come from an allowed page and be one a page cannot send without asking first. */
private fun originRefusal(call: ApplicationCall, origins: BrowserOrigins, hasBody: Boolean): Refusal? {
    val origin = call.request.headers[HttpHeaders.Origin]
    if (origin != null && !origins.allows(origin, call)) {
        return HttpStatusCode.Forbidden to "requests from pages of origin '$origin' may not change kTCS " +
            "(web.allowedOrigins lists the origins that may)"
    }
    val programmatic = hasBody || call.request.headers[CLIENT_HEADER] != null || call.request.headers[HEADER] != null
    val fromBrowser = origin != null || call.request.headers["Sec-Fetch-Site"] != null
    if (!fromBrowser || programmatic) return null
    return HttpStatusCode.Forbidden to "a browser request that changes kTCS needs Content-Type: application/json " +
        "or the $CLIENT_HEADER header"
}
