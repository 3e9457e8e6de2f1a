package org.ktcs.adapters.vda5050.mqtt

import com.hivemq.extension.sdk.api.client.ClientContext
import com.hivemq.extension.sdk.api.interceptor.publish.PublishInboundInterceptor
import java.util.concurrent.ConcurrentHashMap

/**
 * Which of the embedded broker's clients carry [InProcessLink]'s interceptor, and when. HiveMQ hands every inbound
 * publish of a client with an interceptor to its extension executor and back (two thread hops and a handful of
 * objects per message, even for one nobody takes), so while the link only samples (no topic it hears every message
 * of), a client carries the interceptor only while it may publish something the link takes:
 * - on connect, and when the link starts listening to a topic, a client is *learning*: attached until it publishes
 *   on a topic the link listens to, or [MAX_MISSES] times on others (then it stays detached until the next listen);
 * - a client that published on a sampled topic *rests*, detached, until the topic's next message is due; then it
 *   learns again (attached), which costs one hop per message it publishes until the due one.
 *
 * HiveMQ keeps a client's interceptors in a copy-on-write list that it reads once per inbound publish, so attaching
 * and detaching from any thread at run time is safe; a publish already on its way to the interceptor still arrives.
 * Every transition happens under the client's [Tap] lock.
 */
internal class ClientTaps(
    private val interceptor: PublishInboundInterceptor,
    private val onlySampling: () -> Boolean,
    private val later: (delayMillis: Long, task: () -> Unit) -> Unit,
) {
    private val taps = ConcurrentHashMap<String, Tap>()

    /** How many clients carry the interceptor now. */
    val attached: Int get() = taps.values.count { it.isAttached }

    /** A client (re)connected: it learns. A reconnect replaces the tap of the previous connection. */
    fun connected(clientId: String, context: ClientContext) {
        taps[clientId] = Tap(clientId, context).also { it.learn() }
    }

    /** The link listens to another topic: every client that is not resting may publish it. */
    fun listening() = taps.values.forEach { it.learnUnlessResting() }

    /** [clientId] published a message on a topic the link does not listen to. */
    fun missed(clientId: String) {
        taps[clientId]?.missed()
    }

    /**
     * [clientId] published a message on a sampled topic; the link takes the topic's next message in [restMillis]
     * (none taken earlier would be): until then, its messages need not pass the interceptor.
     */
    fun rest(clientId: String, restMillis: Long) {
        taps[clientId]?.rest(restMillis)
    }

    private inner class Tap(private val clientId: String, private val context: ClientContext) {
        private var attached = false
        private var resting = false
        private var misses = 0

        val isAttached: Boolean @Synchronized get() = attached

        @Synchronized
        fun learn() {
            resting = false
            misses = 0
            attach()
        }

        @Synchronized
        fun learnUnlessResting() {
            if (!resting) learn()
        }

        @Synchronized
        fun missed() {
            if (attached && ++misses >= MAX_MISSES && onlySampling()) detach()
        }

        @Synchronized
        fun rest(restMillis: Long) {
            misses = 0
            if (resting || !onlySampling()) return
            resting = true
            detach()
            later(restMillis) { if (taps[clientId] === this) learn() }
        }

        private fun attach() {
            if (!attached) context.addPublishInboundInterceptor(interceptor)
            attached = true
        }

        private fun detach() {
            if (attached) context.removePublishInboundInterceptor(interceptor)
            attached = false
        }
    }

    companion object {
        /**
         * Publishes on topics the link does not listen to before a learning client is left alone: about 2 s of a
         * vehicle that sends state and visualization the driver does not (yet) listen to, or 20 of another client.
         */
        const val MAX_MISSES = 20
    }
}
