package org.ktcs.kernel.web.ws

import io.ktor.websocket.CloseReason
import io.ktor.websocket.WebSocketSession
import io.ktor.websocket.close
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import java.util.concurrent.ConcurrentHashMap

/**
 * The WebSocket sessions open now, so that a clean shutdown can tell each client it is going away (1001) instead of
 * dropping the connection (1006), which clients would report as a failure.
 */
class LiveWebSockets {
    private val sessions = ConcurrentHashMap.newKeySet<WebSocketSession>()

    suspend fun <T> track(session: WebSocketSession, block: suspend () -> T): T {
        sessions += session
        try {
            return block()
        } finally {
            sessions -= session
        }
    }

    /**
     * Closes every session with 1001, waiting at most [timeoutMillis] for the clients to answer. A close frame handed
     * to the engine may still sit in its buffers when the engine stops and drops the connection (the client then sees
     * 1006); a client's answer, which ends its session, says the frame reached it.
     */
    fun closeAll(timeoutMillis: Long = 1_000) = runBlocking {
        withTimeoutOrNull(timeoutMillis) {
            sessions.toList().forEach {
                runCatching { it.close(CloseReason(CloseReason.Codes.GOING_AWAY, "kTCS is stopping")) }
            }
            while (sessions.isNotEmpty()) delay(ANSWER_POLL_MILLIS)
        }
    }

    private companion object {
        const val ANSWER_POLL_MILLIS = 5L
    }
}
