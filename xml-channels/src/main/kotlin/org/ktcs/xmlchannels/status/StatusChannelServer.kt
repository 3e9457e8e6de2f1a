package org.ktcs.xmlchannels.status

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.retry
import kotlinx.coroutines.flow.update
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.model.XmlSafeText
import org.ktcs.xmlchannels.Connection
import org.slf4j.LoggerFactory
import java.util.concurrent.ConcurrentHashMap

/**
 * The status channel: every kernel event a host would see is rendered once and queued for every connected client.
 * A client whose queue is full is dropped, so a client that does not read never holds up the others or the kernel.
 */
internal class StatusChannelServer(private val messages: StatusMessages, private val bufferSize: Int) {
    private val log = LoggerFactory.getLogger(StatusChannelServer::class.java)
    private val clients = ConcurrentHashMap.newKeySet<StatusClient>()
    private val connected = MutableStateFlow(0)

    /** How many clients are connected now. */
    val clientCount: StateFlow<Int> = connected.asStateFlow()

    suspend fun serve(connection: Connection) {
        val client = StatusClient(connection, bufferSize)
        clients += client
        connected.update { it + 1 }
        try {
            client.serve()
        } finally {
            clients -= client
            connected.update { it - 1 }
        }
    }

    /** Broadcasts [events] until cancelled; a subscription that fell behind the kernel is started again. */
    suspend fun broadcast(events: Flow<KernelEvent>) {
        events.retry { error ->
            if (error is CancellationException) return@retry false
            log.warn("XML status channel: subscribing to kernel events again after: {}", error.message)
            delay(RESUBSCRIBE_DELAY)
            true
        }.collect { event ->
            // Rendering XML is the expensive part: with nobody connected there is nobody to render it for.
            if (clients.isNotEmpty()) render(event)?.let { send(it.toByteArray(Charsets.UTF_8)) }
        }
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
