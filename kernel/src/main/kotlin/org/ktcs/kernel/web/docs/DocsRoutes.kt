package org.ktcs.kernel.web.docs

import io.ktor.http.ContentType
import io.ktor.http.HttpStatusCode
import io.ktor.server.response.respond
import io.ktor.server.response.respondBytes
import io.ktor.server.response.respondRedirect
import io.ktor.server.response.respondText
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.route

/**
 * `GET /v1/openapi.yaml` and `GET /v1/openapi.json`: the document, behind the access key like the rest of `/v1`.
 * The document is read on the first request, not while kTCS starts.
 */
fun Route.openApiRoutes(document: Lazy<ApiDocument>) {
    get("/openapi.yaml") { call.respondText(document.value.yaml, YAML) }
    get("/openapi.json") { call.respondText(document.value.json, ContentType.Application.Json) }
}

/**
 * `/docs/`: Swagger UI for the document, served from the swagger-ui webjar so it works without internet access, and
 * `/docs/websocket.html`, the WebSocket protocol. Outside `/v1`, so a browser opens them even with an access key
 * (the document describes the API, it grants nothing); Swagger UI's *Authorize* sends the key for *Try it out*.
 */
fun Route.docsRoutes(document: Lazy<ApiDocument>) {
    val websocketPage = lazy { WebSocketPage.render(document.value) }
    get("/docs") { call.respondRedirect("/docs/") }
    route("/docs") {
        get("/") { call.respondText(page("index.html"), ContentType.Text.Html) }
        get("/swagger-initializer.js") { call.respondText(page("swagger-initializer.js"), JAVASCRIPT) }
        get("/openapi.yaml") { call.respondText(document.value.yaml, YAML) }
        get("/websocket.html") { call.respondText(websocketPage.value, ContentType.Text.Html) }
        get("/{file}") {
            val asset =
                SwaggerUiWebjar.asset(call.parameters["file"]!!) ?: return@get call.respond(HttpStatusCode.NotFound)
            call.respondBytes(asset.bytes, asset.contentType)
        }
    }
}

private fun page(name: String): String =
    requireNotNull(ApiDocument::class.java.getResource("/org/ktcs/kernel/web/docs/$name")) { "$name is not in the jar" }
        .readText()

private val YAML = ContentType("application", "yaml")
private val JAVASCRIPT = ContentType("text", "javascript")
