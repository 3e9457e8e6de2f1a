package org.ktcs.kernel.web.plugins

import io.ktor.http.ContentType
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.Application
import io.ktor.server.application.ApplicationCall
import io.ktor.server.application.install
import io.ktor.server.plugins.BadRequestException
import io.ktor.server.plugins.statuspages.StatusPages
import io.ktor.server.response.respondText
import kotlinx.serialization.builtins.ListSerializer
import kotlinx.serialization.builtins.serializer
import kotlinx.serialization.json.Json
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.error.ObjectUnknownException
import org.slf4j.LoggerFactory

/**
 * Maps errors to HTTP as openTCS's web API does, in one place: 400 for bad input, 404 for unknown objects, 409 for
 * existing names and illegal state changes, each with a JSON array of readable messages. Anything else is a bug:
 * logged with its stack trace, answered 500 without details.
 */
fun Application.installErrorResponses() {
    val log = LoggerFactory.getLogger("org.ktcs.kernel.web")
    install(StatusPages) {
        exception<InvalidRequestException> { call, error ->
            call.respondErrors(HttpStatusCode.BadRequest, error.message)
        }
        exception<BadRequestException> { call, error ->
            call.respondErrors(HttpStatusCode.BadRequest, error.rootMessage())
        }
        exception<ObjectUnknownException> { call, error -> call.respondErrors(HttpStatusCode.NotFound, error.message) }
        exception<ObjectExistsException> { call, error -> call.respondErrors(HttpStatusCode.Conflict, error.message) }
        exception<IllegalStateChangeException> { call, error ->
            call.respondErrors(HttpStatusCode.Conflict, error.message)
        }
        exception<Throwable> { call, error ->
            log.error("request {} {} failed", call.request.local.method.value, call.request.local.uri, error)
            call.respondErrors(HttpStatusCode.InternalServerError, "internal error; the kTCS log has the details")
        }
        status(HttpStatusCode.NotFound) { call, _ ->
            call.respondErrors(
                HttpStatusCode.NotFound,
                "no such resource: ${call.request.local.method.value} ${call.request.local.uri}",
            )
        }
    }
}

/** Answers [status] with openTCS's error body: a JSON array of messages. */
suspend fun ApplicationCall.respondErrors(status: HttpStatusCode, vararg messages: String?) {
    val body = Json.encodeToString(ListSerializer(String.serializer()), messages.map { it ?: status.description })
    respondText(body, ContentType.Application.Json, status)
}

private fun Throwable.rootMessage(): String = generateSequence(this) { it.cause }.last().message ?: "bad request"
