package org.ktcs.xmlchannels.status

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.model.XmlSafeText
import org.ktcs.xmlchannels.Connection
import org.slf4j.LoggerFactory
import java.util.concurrent.ConcurrentHashMap

/**
 * The status channel: every kernel event a host would see is rendered once and queued for every connected client.
 * A client whose queue is full is dropped, so a client that does not read never holds up the others or the kernel.
 *
 * It follows the kernel's events (with [subscribe], in [scope]) only while a client is connected: with nobody
 * connected every event would wake a thread only to be dropped (README, "Performance").
 */
internal class StatusChannelServer(
    private val messages: StatusMessages,
    private val bufferSize: Int,
    private val scope: CoroutineScope,
    private val subscribe: suspend () -> Flow<KernelEvent>,
) {
    private val log = LoggerFactory.getLogger(StatusChannelServer::class.java)
    private val clients = ConcurrentHashMap.newKeySet<StatusClient>()
    private val connected = MutableStateFlow(0)

    /** The kernel events followed for the clients connected now; guarded by [clients]' monitor with them. */
    private var subscription: Subscription? = null

    private class Subscription(val job: Job, val live: CompletableDeferred<Unit>)

    /** How many clients are connected now, each counted once it gets every event published from then on. */
    val clientCount: StateFlow<Int> = connected.asStateFlow()

    suspend fun serve(connection: Connection) {
        val client = StatusClient(connection, bufferSize)
        val live = synchronized(clients) {
            clients += client
            (subscription ?: follow().also { subscription = it }).live
        }
        try {
            live.await()
            connected.update { it + 1 }
            try {
                client.serve()
            } finally {
                connected.update { it - 1 }
            }
        } finally {
            synchronized(clients) {
                clients -= client
                if (clients.isEmpty()) {
                    subscription?.job?.cancel()
                    subscription = null
                }
            }
        }
    }

    /** Follows the kernel's events until cancelled; a subscription that fell behind the kernel is started again. */
    private fun follow(): Subscription {
        val live = CompletableDeferred<Unit>()
        val job = scope.launch {
            while (true) {
                try {
                    val events = subscribe()
                    live.complete(Unit)
                    events.collect { event -> render(event)?.let { send(it.toByteArray(Charsets.UTF_8)) } }
                } catch (error: CancellationException) {
                    throw error
                } catch (error: Exception) {
                    log.warn("XML status channel: subscribing to kernel events again after: {}", error.message)
                }
                delay(RESUBSCRIBE_DELAY)
            }
        }
        return Subscription(job, live)
    }

    /** One event that cannot be rendered (kernel checks names, but extensions may not) is skipped, not fatal. */
    private fun render(event: KernelEvent): String? = try {
        messages.render(event)
    } catch (error: Exception) {
        log.warn(
            "XML status channel: skipped a message that cannot be written as XML: {}",
            error.message?.let(XmlSafeText::printable),
        )
        null
    }

    private fun send(document: ByteArray) {
        clients.forEach { client ->
            if (!client.offer(document) && clients.remove(client)) {
                log.warn(
                    "XML status channel: dropped {}, it does not keep up ({} messages queued)",
                    client.address,
                    bufferSize,
                )
                client.close()
            }
        }
    }
}

private const val RESUBSCRIBE_DELAY = 100L
