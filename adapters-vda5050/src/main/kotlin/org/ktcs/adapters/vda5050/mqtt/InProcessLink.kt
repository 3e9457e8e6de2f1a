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
import com.hivemq.extension.sdk.api.services.Services
import com.hivemq.extension.sdk.api.services.builder.Builders
import com.hivemq.extension.sdk.api.services.publish.PublishService
import com.hivemq.extension.sdk.api.services.publish.RetainedMessageStore
import org.slf4j.LoggerFactory
import java.nio.ByteBuffer
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.atomic.AtomicBoolean

/**
 * The driver's link to the embedded broker from inside it (an [EmbeddedExtension] of kTCS's HiveMQ): a publish
 * inbound interceptor hands each vehicle message to the driver as the broker receives it, on the broker's threads,
 * without delivering it over TCP to an MQTT client of kTCS's and decoding it a second time; orders and instant actions
 * go out through the broker's publish service. Delivery to other subscribers is untouched.
 *
 * Messages the broker publishes itself never pass an inbound interceptor: a client's last will, and a retained message
 * published before the driver listened. The first reaches the driver through the `connection` topic, which the
 * driver hears through kTCS's MQTT client of the broker; for the second, [listen] hands over the
 * topic's retained message.
 */
class InProcessLink : MessageLink {
    private val log = LoggerFactory.getLogger(InProcessLink::class.java)
    private val handlers = ConcurrentHashMap<String, (ByteBuffer) -> Unit>()

    @Volatile private var publishing: PublishService? = null

    @Volatile private var retained: RetainedMessageStore? = null

    private val interceptor = PublishInboundInterceptor { input: PublishInboundInput, _: PublishInboundOutput ->
        val packet = input.publishPacket
        val handler = handlers[packet.topic]
        if (handler != null) deliver(packet.topic, handler, packet.payload.orElse(MessageLink.EMPTY_PAYLOAD))
    }

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
                    Services.initializerRegistry().setClientInitializer { _, client ->
                        client.addPublishInboundInterceptor(interceptor)
                    }
                }

                override fun extensionStop(input: ExtensionStopInput, output: ExtensionStopOutput) {
                    publishing = null
                    retained = null
                }
            },
        )
        .build()

    override fun listen(topic: String, qos: Int, handler: (ByteBuffer) -> Unit) {
        val heardLive = AtomicBoolean(false)
        handlers[topic] = { payload ->
            heardLive.set(true)
            handler(payload)
        }
        // The store answers asynchronously: a message published meanwhile is newer than the retained one.
        retained?.getRetainedMessage(topic)?.thenAccept { message ->
            if (!heardLive.get()) message.flatMap { it.payload }.ifPresent { deliver(topic, handler, it) }
        }
    }

    override fun stopListening(topic: String) {
        handlers.remove(topic)
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
    private fun deliver(topic: String, handler: (ByteBuffer) -> Unit, payload: ByteBuffer) {
        try {
            handler(payload)
        } catch (error: RuntimeException) {
            log.warn("a message on {} could not be handled: {}", topic, error.toString())
        }
    }
}
