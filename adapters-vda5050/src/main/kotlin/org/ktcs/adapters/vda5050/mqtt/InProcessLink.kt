package org.ktcs.adapters.vda5050.mqtt

import com.hivemq.embedded.EmbeddedExtension
import com.hivemq.extension.sdk.api.ExtensionMain
import com.hivemq.extension.sdk.api.interceptor.publish.PublishInboundInterceptor
import com.hivemq.extension.sdk.api.interceptor.publish.parameter.PublishInboundInput
import com.hivemq.extension.sdk.api.interceptor.publish.parameter.PublishInboundOutput
import com.hivemq.extension.sdk.api.packets.general.Qos
import com.hivemq.extension.sdk.api.parameter.ExtensionStartInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStartOutput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopOutput
import com.hivemq.extension.sdk.api.services.ManagedExtensionExecutorService
import com.hivemq.extension.sdk.api.services.Services
import com.hivemq.extension.sdk.api.services.builder.Builders
import com.hivemq.extension.sdk.api.services.publish.PublishService
import com.hivemq.extension.sdk.api.services.publish.RetainedMessageStore
import org.slf4j.LoggerFactory
import java.nio.ByteBuffer
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.atomic.AtomicLong

/**
 * The driver's link to the embedded broker from inside it (an [EmbeddedExtension] of kTCS's HiveMQ): a publish
 * inbound interceptor hands a vehicle's message to the driver as the broker receives it, on the broker's threads,
 * without delivering it over TCP to an MQTT client of kTCS's and decoding it a second time; orders and instant actions
 * go out through the broker's publish service. Delivery to other subscribers is untouched.
 *
 * The interceptor costs a hop to HiveMQ's extension executor and back for every message of a client that carries it,
 * taken or not. So for a topic the driver only [sample]s (visualization: one message per `minVisualizationInterval`
 * of ten), a vehicle's client carries it only from the moment the topic's next message is due until one is taken
 * ([ClientTaps]), as long as the link hears no topic's every message (with one [listen], every client carries it).
 * What the driver must hear in full (state, factsheet, connection) comes through kTCS's MQTT client instead.
 *
 * Messages the broker publishes itself never pass an inbound interceptor: a client's last will, and a retained message
 * published before the driver listened. For the second, [listen] hands over the topic's retained message.
 */
class InProcessLink : MessageLink {
    private val log = LoggerFactory.getLogger(InProcessLink::class.java)
    private val listeners = ConcurrentHashMap<String, Listener>()
    private val everyMessage = AtomicInteger()

    @Volatile private var publishing: PublishService? = null

    @Volatile private var retained: RetainedMessageStore? = null

    @Volatile private var executor: ManagedExtensionExecutorService? = null

    /** How many messages passed the interceptor (taken or not): what HiveMQ's extension executor handled. */
    val intercepted = AtomicLong()

    private val interceptor = PublishInboundInterceptor { input: PublishInboundInput, _: PublishInboundOutput ->
        intercepted.incrementAndGet()
        val packet = input.publishPacket
        val clientId = input.clientInformation.clientId
        val listener = listeners[packet.topic]
        if (listener == null) {
            taps.missed(clientId)
        } else {
            val taken = deliver(packet.topic, listener, packet.payload.orElse(MessageLink.EMPTY_PAYLOAD))
            if (listener.intervalMillis > 0) taps.rest(clientId, listener.restMillis(taken))
        }
    }

    private val taps: ClientTaps = ClientTaps(interceptor, onlySampling = { everyMessage.get() == 0 }) { delay, task ->
        executor?.schedule(Runnable(task), delay, TimeUnit.MILLISECONDS)
    }

    /** How many of the broker's clients carry the interceptor now. */
    val tappedClients: Int get() = taps.attached

    /** What the embedded broker is built with. */
    val extension: EmbeddedExtension = EmbeddedExtension.builder()
        .withId("ktcs-vda5050")
        .withName("kTCS VDA 5050 driver")
        .withVersion("1")
        .withExtensionMain(
            object : ExtensionMain {
                override fun extensionStart(input: ExtensionStartInput, output: ExtensionStartOutput) {
                    publishing = Services.publishService()
                    retained = Services.retainedMessageStore()
                    executor = Services.extensionExecutorService()
                    Services.initializerRegistry().setClientInitializer { initializer, client ->
                        taps.connected(initializer.clientInformation.clientId, client)
                    }
                }

                override fun extensionStop(input: ExtensionStopInput, output: ExtensionStopOutput) {
                    publishing = null
                    retained = null
                    executor = null
                }
            },
        )
        .build()

    override fun listen(topic: String, qos: Int, handler: (ByteBuffer) -> Unit) {
        val heardLive = AtomicBoolean(false)
        val listener = Listener(0) { payload ->
            heardLive.set(true)
            handler(payload)
            true
        }
        replace(topic, listener)
        // The store answers asynchronously: a message published meanwhile is newer than the retained one.
        retained?.getRetainedMessage(topic)?.thenAccept { message ->
            if (!heardLive.get()) message.flatMap { it.payload }.ifPresent { deliver(topic, listener, it) }
        }
    }

    override fun sample(topic: String, qos: Int, intervalMillis: Long, handler: (ByteBuffer) -> Boolean) {
        require(intervalMillis > 0) { "a sampled topic needs a positive interval, not $intervalMillis ms" }
        replace(topic, Listener(intervalMillis, handler))
    }

    override fun stopListening(topic: String) = replace(topic, null)

    @Synchronized
    private fun replace(topic: String, listener: Listener?) {
        val previous = if (listener == null) listeners.remove(topic) else listeners.put(topic, listener)
        if (previous?.intervalMillis == 0L) everyMessage.decrementAndGet()
        if (listener?.intervalMillis == 0L) everyMessage.incrementAndGet()
        if (listener != null) taps.listening()
    }

    override fun send(topic: String, payload: ByteArray, qos: Int) {
        val service = checkNotNull(publishing) { "the embedded MQTT broker is not running" }
        val publish = Builders.publish().topic(topic).payload(ByteBuffer.wrap(payload))
            .qos(Qos.valueOf(qos.coerceIn(0, 2))).build()
        service.publish(publish).whenComplete { _, error ->
            if (error != null) log.warn("could not publish to {}: {}", topic, error.message)
        }
    }

    // An exception escaping an interceptor would make HiveMQ drop the vehicle's message for every subscriber.
    private fun deliver(topic: String, listener: Listener, payload: ByteBuffer): Boolean = try {
        listener.handler(payload)
    } catch (error: RuntimeException) {
        log.warn("a message on {} could not be handled: {}", topic, error.toString())
        true
    }

    /** A topic the link hears: every message ([intervalMillis] 0) or at most one per [intervalMillis]. */
    private class Listener(val intervalMillis: Long, val handler: (ByteBuffer) -> Boolean) {
        @Volatile private var takenAt = Long.MIN_VALUE

        /** How long after this message the topic's next one is due: [intervalMillis] after the last one taken. */
        fun restMillis(taken: Boolean): Long {
            val now = System.currentTimeMillis()
            if (taken) takenAt = now
            val last = takenAt
            return if (last == Long.MIN_VALUE) {
                MIN_REST_MILLIS
            } else {
                (last + intervalMillis - now).coerceAtLeast(
                    MIN_REST_MILLIS,
                )
            }
        }
    }

    private companion object {
        /** A message declined before its due time (another client's, or a clock step): rest at least this long. */
        const val MIN_REST_MILLIS = 10L
    }
}
