package org.ktcs.adapters.vda5050.broker

import io.netty.buffer.ByteBuf
import io.netty.buffer.ByteBufUtil
import io.netty.buffer.Unpooled
import org.slf4j.LoggerFactory
import java.nio.ByteBuffer

/**
 * The broker's state and its one rule: a message goes to the in-process listener of its topic, to every session whose
 * subscription matches it, and, with the retain flag, into the retained messages. Everything here runs on the
 * broker's single event loop, so nothing is locked.
 */
internal class Routing {
    private val log = LoggerFactory.getLogger(BuiltinBroker::class.java)
    private val sessions = HashMap<String, Session>()
    private val tree = TopicTree()
    private val retained = RetainedMessages()
    private val listeners = HashMap<String, (ByteBuffer) -> Unit>()
    private val matched = HashMap<Session, Int>()

    /** How many PUBLISH packets clients have sent the broker. */
    @Volatile var publishesReceived = 0L
        private set

    /** Routes a message; [payload] stays the caller's (each delivery takes its own reference). */
    fun publish(topic: String, payload: ByteBuf, qos: Int, retain: Boolean) {
        if (retain) retained.put(topic, ByteBufUtil.getBytes(payload), qos)
        listeners[topic]?.let { hand(topic, it, payload.nioBuffer().asReadOnlyBuffer()) }
        matched.clear()
        tree.forEachMatch(topic) { session, granted -> matched.merge(session, granted, ::maxOf) }
        matched.forEach { (session, granted) ->
            session.connection?.send(topic, payload, minOf(qos, granted), retain = false)
        }
    }

    /** Counts a PUBLISH a client sent and routes it. */
    fun received(topic: String, payload: ByteBuf, qos: Int, retain: Boolean) {
        publishesReceived++
        publish(topic, payload, qos, retain)
    }

    /**
     * Gives [connection] the session of [clientId], taking it over from a connection that still holds it; the
     * session is new unless the client asked to resume it and it was persistent. The second value: whether an earlier
     * session resumed (the CONNACK's session present flag).
     */
    fun attach(
        clientId: String,
        connection: ClientConnection,
        cleanStart: Boolean,
        persistent: Boolean,
    ): Pair<Session, Boolean> {
        val earlier = sessions[clientId]
        earlier?.connection?.takenOver()
        val session = earlier?.takeIf { it.persistent && !cleanStart } ?: Session(clientId, persistent)
        val resumed = session === earlier
        if (earlier != null && !resumed) drop(earlier)
        session.connection = connection
        sessions[clientId] = session
        return session to resumed
    }

    /** [connection] ended: a session that is not persistent ends with it. */
    fun detach(session: Session, connection: ClientConnection) {
        if (session.connection !== connection) return
        session.connection = null
        if (!session.persistent) {
            drop(session)
            sessions.remove(session.clientId)
        }
    }

    fun subscribe(session: Session, filter: String, qos: Int) {
        tree.add(filter, session, qos)
        session.filters[filter] = qos
    }

    fun unsubscribe(session: Session, filter: String): Boolean {
        session.filters.remove(filter)
        return tree.remove(filter, session)
    }

    /** The retained messages matching [filter], as a subscription to it receives them. */
    fun retainedFor(filter: String): List<Retained> = retained.matching(filter)

    /** Hands [handler] every message on [topic], starting with its retained message if it has one. */
    fun listen(topic: String, handler: (ByteBuffer) -> Unit) {
        listeners[topic] = handler
        retained[topic]?.let { hand(topic, handler, ByteBuffer.wrap(it.payload).asReadOnlyBuffer()) }
    }

    fun stopListening(topic: String) {
        listeners.remove(topic)
    }

    private fun drop(session: Session) {
        session.filters.keys.forEach { tree.remove(it, session) }
        session.filters.clear()
    }

    // A listener's failure must not keep the message from the other subscribers.
    private fun hand(topic: String, handler: (ByteBuffer) -> Unit, payload: ByteBuffer) {
        try {
            handler(payload)
        } catch (error: RuntimeException) {
            log.warn("a message on {} could not be handled: {}", topic, error.toString())
        }
    }

    companion object {
        /** A payload the broker publishes from bytes it holds. */
        fun payloadOf(bytes: ByteArray): ByteBuf = Unpooled.wrappedBuffer(bytes)
    }
}
