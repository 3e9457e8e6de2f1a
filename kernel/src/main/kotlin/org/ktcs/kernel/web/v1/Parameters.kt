package org.ktcs.kernel.web.v1

import io.ktor.http.BadContentTypeFormatException
import io.ktor.http.HttpHeaders
import io.ktor.server.application.ApplicationCall
import io.ktor.server.plugins.BadRequestException
import io.ktor.server.request.contentCharset
import io.ktor.server.request.contentLength
import io.ktor.server.request.receiveText
import io.ktor.server.routing.RoutingCall
import io.ktor.utils.io.core.readText
import io.ktor.utils.io.readRemaining
import kotlinx.serialization.DeserializationStrategy
import kotlinx.serialization.serializer
import org.ktcs.api.error.InvalidRequestException

/**
 * The path parameter [name]; routes only match when it is there. Read from the route's path parameters: a query
 * parameter of the same name must not rename the object (Ktor's merged `parameters` list the query's first), and
 * merging the two into a new map cost every request a few allocations for nothing.
 */
fun ApplicationCall.pathName(name: String = "NAME"): String =
    ((this as? RoutingCall)?.pathParameters ?: parameters)[name] ?: throw InvalidRequestException("$name is missing")

/** The boolean query parameter [name], [default] when absent; anything but true/false is refused. */
fun ApplicationCall.booleanQuery(name: String, default: Boolean = false): Boolean {
    val raw = request.queryParameters[name] ?: return default
    return raw.lowercase().toBooleanStrictOrNull()
        ?: throw InvalidRequestException("query parameter $name must be true or false, was '$raw'")
}

/** The required boolean query parameter [name]: true or false. */
fun ApplicationCall.requiredBooleanQuery(name: String): Boolean {
    requiredQuery(name)
    return booleanQuery(name)
}

/** The required query parameter [name]. */
fun ApplicationCall.requiredQuery(name: String): String =
    request.queryParameters[name] ?: throw InvalidRequestException("query parameter $name is missing")

/** The request body decoded as [T], with malformed JSON refused as bad input. */
suspend inline fun <reified T> ApplicationCall.receiveJson(): T = receiveJson(serializer<T>())

/** The request body decoded with [deserializer]: without looking up the serializer of a reified type per request. */
suspend fun <T> ApplicationCall.receiveJson(deserializer: DeserializationStrategy<T>): T =
    V1Json.decodeRequest(deserializer, receiveBodyText())

/**
 * The request body as text, read as Ktor's `receiveText` reads it (in the charset the Content-Type names, else
 * UTF-8). A body with a Content-Length, which RequestSizeLimit checked before the handler ran, is read from the
 * connection directly: Ktor's receive pipeline took 27 of the 105 µs a POST of an order spent in its handler, the
 * reading itself 4. A body without one (chunked) goes through the pipeline, where RequestSizeLimit counts it.
 */
suspend fun ApplicationCall.receiveBodyText(): String {
    if (request.contentLength() == null) return receiveText()
    val charset = try {
        request.contentCharset()
    } catch (cause: BadContentTypeFormatException) {
        throw BadRequestException("Illegal Content-Type format: ${request.headers[HttpHeaders.ContentType]}", cause)
    } ?: Charsets.UTF_8
    return request.receiveChannel().readRemaining().readText(charset)
}
