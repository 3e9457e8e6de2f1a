package org.ktcs.kernel.web.ws

import io.ktor.server.websocket.DefaultWebSocketServerSession
import io.ktor.websocket.CloseReason
import io.ktor.websocket.Frame
import io.ktor.websocket.FrameTooBigException
import io.ktor.websocket.close
import io.ktor.websocket.readText
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Job
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.serialization.SerializationException
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.PlantModelReplacedEvent
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.events.SubscriberTooSlowException
import org.ktcs.kernel.web.v1.V1Json

/**
 * One WebSocket client. It subscribes to topics; it gets a snapshot of each, then every change in kernel order.
 * Events wait in a buffer of [capacity]; a client that falls that far behind is told it missed events and gets
 * fresh snapshots, so it never slows the kernel or the other clients.
 */
class WsSession internal constructor(
    private val socket: DefaultWebSocketServerSession,
    private val services: KernelServices,
    private val capacity: Int = 1000,
    private val encoded: EncodedObjects = EncodedObjects(),
) {
    private val json = V1Json.json
    private var topics = emptySet<WsTopic>()
    private var withPrevious = true
    private var omitUnchanged = false
    private var shortenedLists = false
    private var onlyChanged = false
    private var sequence = 0L

    suspend fun run() = coroutineScope {
        var feed: Job? = null
        try {
            for (frame in socket.incoming) {
                if (frame !is Frame.Text) continue
                val message = parseSubscription(frame.readText()) ?: continue
                feed?.cancelAndJoin()
                topics = message.topics.mapNotNullTo(LinkedHashSet(), WsTopic::of)
                withPrevious = message.previous
                omitUnchanged = message.omitUnchanged
                shortenedLists = message.shortenedLists
                onlyChanged = message.onlyChanged
                feed = launch { streamForever() }
            }
        } catch (error: FrameTooBigException) {
            // The client's fault, not kTCS's: answered with 1009, not logged as a failure.
            feed?.cancel()
            socket.close(CloseReason(CloseReason.Codes.TOO_BIG, "a frame of ${error.frameSize} bytes is too big"))
        }
        feed?.cancel()
    }

    private suspend fun parseSubscription(text: String): WsClientMessage? {
        val message = try {
            json.decodeFromString<WsClientMessage>(text)
        } catch (error: SerializationException) {
            return null.also { send(WsError("not a kTCS WebSocket message: ${error.message}")) }
        } catch (error: IllegalArgumentException) {
            return null.also { send(WsError("not a kTCS WebSocket message: ${error.message}")) }
        }
        if (message.type != "subscribe") {
            return null.also { send(WsError("unknown message type '${message.type}'; expected 'subscribe'")) }
        }
        if (message.shortenedLists && !message.omitUnchanged && !message.onlyChanged) {
            return null.also {
                send(WsError("shortenedLists needs omitUnchanged or onlyChanged: the client keeps the lists it cuts"))
            }
        }
        if (message.topics.isEmpty()) {
            return null.also { send(WsError("subscribe needs topics, one or more of $KNOWN_TOPICS")) }
        }
        val unknown = message.topics.filter { WsTopic.of(it) == null }
        if (unknown.isNotEmpty()) {
            return null.also { send(WsError("unknown topics $unknown; known: $KNOWN_TOPICS")) }
        }
        return message
    }

    private suspend fun streamForever(): Nothing = coroutineScope {
        while (true) {
            // The snapshots and the subscription are taken in one kernel step, so no change falls between them
            // and none is sent twice.
            val (snapshots, changes) = services.eventsAfter {
                topics.map { WsSnapshot(it.wireName, WsTopics.snapshot(it, services)) }
            }
            val events = Channel<KernelEvent>(capacity)
            val collector = launch(start = CoroutineStart.UNDISPATCHED) {
                try {
                    changes.collect {
                        if (!events.trySend(it).isSuccess) events.close(SubscriberTooSlowException())
                    }
                } catch (error: SubscriberTooSlowException) {
                    events.close(error)
                }
            }
            snapshots.forEach { send(it) }
            try {
                for (event in events) {
                    val batch = waiting(event, events)
                    val replaced = batch.indexOfFirst { it is PlantModelReplacedEvent }
                    forward(if (replaced < 0) batch else batch.subList(0, replaced))
                    if (replaced >= 0) {
                        send(WsModelReplaced((batch[replaced] as PlantModelReplacedEvent).model.name))
                        break
                    }
                }
            } catch (error: SubscriberTooSlowException) {
                send(WsMissed("the client read too slowly; more than $capacity events were waiting"))
            }
            collector.cancel()
        }
        @Suppress("UNREACHABLE_CODE")
        error("unreachable")
    }

    /**
     * [first] and the events behind it, at most [BATCH]: sent together, merged, with one flush. When nothing else
     * waits yet, the events of the next [LINGER_MILLIS] join it: a kernel step publishes several, and waking the
     * session, encoding and flushing for each alone costs most of the stream's CPU; a client sees them a few ms
     * later.
     */
    private suspend fun waiting(first: KernelEvent, events: Channel<KernelEvent>): List<KernelEvent> {
        val batch = arrayListOf(first)
        drain(events, batch)
        if (batch.size == 1) {
            delay(LINGER_MILLIS)
            drain(events, batch)
        }
        return batch
    }

    private fun drain(events: Channel<KernelEvent>, batch: MutableList<KernelEvent>) {
        while (batch.size < BATCH) batch += events.tryReceive().getOrNull() ?: break
    }

    private suspend fun forward(batch: List<KernelEvent>) {
        // Encoding is the costly part: events of topics the client did not ask for are not encoded at all.
        val wanted = batch.filter { WsTopics.topicOf(it) in topics }
        if (wanted.isEmpty()) return
        for (event in WsBatch.coalesce(wanted)) {
            val change = WsTopics.change(event, encoded) ?: continue
            val changed = if (onlyChanged) ChangedFields.of(event) else null
            val unchanged = if (omitUnchanged && changed == null) Unchanged.fieldsOf(event) else emptyList()
            val shortened = if (shortenedLists) Unchanged.shortenedOf(event) else emptyMap()
            socket.send(Frame.Text(true, change.eventBytes(sequence++, withPrevious, unchanged, shortened, changed)))
        }
        flush()
    }

    private suspend fun send(message: WsServerMessage) = sendFrame(
        Frame.Text(true, utf8(json.encodeToString(WsServerMessage.serializer(), message))),
    )

    private suspend fun sendFrame(frame: Frame) {
        socket.send(frame)
        flush()
    }

    private suspend fun flush() {
        // Sending only queues the frame, without limit; waiting for it to be written is what lets a client that
        // reads slowly hold this session up, so that its event buffer fills and it is told it missed events.
        socket.flush()
    }
}

private val KNOWN_TOPICS = WsTopic.entries.map { it.wireName }

/** At most this many waiting events go out together (merged where they can be, with one flush). */
private const val BATCH = 256

/** How long a lone event waits for others to go out with. */
private const val LINGER_MILLIS = 5L
