package org.ktcs.kernel.web.plugins

import io.ktor.http.ContentType
import io.ktor.http.HttpStatusCode
import io.ktor.http.cio.ParserException
import io.ktor.http.content.OutgoingContent
import io.ktor.server.application.Application
import io.ktor.server.application.ApplicationCall
import io.ktor.server.application.install
import io.ktor.server.plugins.BadRequestException
import io.ktor.server.plugins.PayloadTooLargeException
import io.ktor.server.plugins.statuspages.StatusPages
import io.ktor.server.plugins.statuspages.StatusPagesConfig
import io.ktor.server.response.respondText
import kotlinx.serialization.builtins.ListSerializer
import kotlinx.serialization.builtins.serializer
import kotlinx.serialization.json.Json
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.error.ObjectUnknownException
import org.slf4j.LoggerFactory
import java.io.IOException
import kotlin.coroutines.cancellation.CancellationException

/**
 * Maps errors to HTTP as openTCS's web API does, in one place: 400 for bad input, 404 for unknown objects, 409 for
 * existing names and illegal state changes, 413 for bodies over the limit, each with a JSON array of readable messages.
 * A request the server cannot read (a malformed chunked body, a client that hangs up) is the client's fault: 400, and
 * a DEBUG line, so that no client can fill the log. Any other error status without a JSON body (405 from routing,
 * say) gets a JSON array naming it, so every error has openTCS's shape. Anything else is a bug: logged with its
 * stack trace, answered 500 without details.
 */
fun Application.installErrorResponses() {
    val log = LoggerFactory.getLogger("org.ktcs.kernel.web")
    install(StatusPages) {
        answer<InvalidRequestException> { call, error ->
            call.respondErrors(HttpStatusCode.BadRequest, error.message)
        }
        answer<PayloadTooLargeException> { call, error -> call.respondTooLarge(error) }
        answer<BadRequestException> { call, error ->
            val tooLarge = error.causes().filterIsInstance<PayloadTooLargeException>().firstOrNull()
            if (tooLarge != null) return@answer call.respondTooLarge(tooLarge)
            call.respondErrors(HttpStatusCode.BadRequest, error.rootMessage())
        }
        answer<ObjectUnknownException> { call, error -> call.respondErrors(HttpStatusCode.NotFound, error.message) }
        answer<ObjectExistsException> { call, error -> call.respondErrors(HttpStatusCode.Conflict, error.message) }
        answer<IllegalStateChangeException> { call, error ->
            call.respondErrors(HttpStatusCode.Conflict, error.message)
        }
        answer<CancellationException> { call, error ->
            // A stream (SSE, long polling) ended because the server stops or the client left: nothing went wrong.
            log.debug(
                "request {} {} ended: {}",
                call.request.local.method.value,
                call.request.local.uri,
                error.toString(),
            )
        }
        answer<Throwable> { call, error ->
            if (error.causes().any { it is IOException || it is ParserException }) {
                log.debug(
                    "request {} {} could not be read: {}",
                    call.request.local.method.value,
                    call.request.local.uri,
                    error.toString(),
                )
                return@answer call.respondErrors(
                    HttpStatusCode.BadRequest,
                    "the request could not be read: ${error.rootMessage()}",
                )
            }
            log.error("request {} {} failed", call.request.local.method.value, call.request.local.uri, error)
            call.respondErrors(HttpStatusCode.InternalServerError, "internal error; the kTCS log has the details")
        }
        HttpStatusCode.allStatusCodes.filter { it.value >= 400 }.forEach { code ->
            statuses[code] = StatusAnswer(code) { call, content ->
                if (!content.isJson()) call.respondErrors(code, describe(call, code))
            }
        }
    }
}

/*
 * StatusPages writes a TRACE line naming the handler before it runs one, building the text whether TRACE is on or
 * not; a lambda's toString renders its signature through Kotlin reflection, a third of a 404's CPU.
 * These handlers name themselves cheaply.
 */
private inline fun <reified T : Throwable> StatusPagesConfig.answer(
    noinline answer: suspend (ApplicationCall, T) -> Unit,
) =
    exception(T::class, ExceptionAnswer(T::class.java.simpleName, answer))

private class ExceptionAnswer<T : Throwable>(
    private val name: String,
    private val answer: suspend (ApplicationCall, T) -> Unit,
) : suspend (ApplicationCall, T) -> Unit {
    override suspend fun invoke(call: ApplicationCall, error: T) = answer(call, error)

    override fun toString() = "answer to $name"
}

private class StatusAnswer(
    private val code: HttpStatusCode,
    private val answer: suspend (ApplicationCall, OutgoingContent) -> Unit,
) : suspend (ApplicationCall, OutgoingContent, HttpStatusCode) -> Unit {
    override suspend fun invoke(call: ApplicationCall, content: OutgoingContent, status: HttpStatusCode) =
        answer(call, content)

    override fun toString() = "answer to status ${code.value}"
}

private fun describe(call: ApplicationCall, code: HttpStatusCode): String {
    val request = "${call.request.local.method.value} ${call.request.local.uri}"
    return when (code) {
        HttpStatusCode.NotFound -> "no such resource: $request"
        HttpStatusCode.MethodNotAllowed -> "method not allowed: $request"
        else -> "${code.description}: $request"
    }
}

private fun OutgoingContent.isJson(): Boolean = contentType?.match(ContentType.Application.Json) == true

private suspend fun ApplicationCall.respondTooLarge(error: PayloadTooLargeException) =
    respondErrors(HttpStatusCode.PayloadTooLarge, error.message ?: "request body too large")

private fun Throwable.causes(): Sequence<Throwable> = generateSequence(this) { it.cause }

/** Answers [status] with openTCS's error body: a JSON array of messages. */
suspend fun ApplicationCall.respondErrors(status: HttpStatusCode, vararg messages: String?) {
    val body = Json.encodeToString(ListSerializer(String.serializer()), messages.map { it ?: status.description })
    respondText(body, ContentType.Application.Json, status)
}

private fun Throwable.rootMessage(): String = generateSequence(this) { it.cause }.last().message ?: "bad request"
