package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.broker.BrokerConfig
import org.ktcs.adapters.vda5050.broker.BuiltinBroker
import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import org.ktcs.adapters.vda5050.mqtt.EmbeddedBroker
import org.ktcs.adapters.vda5050.mqtt.EmbeddedBrokerKind
import org.ktcs.adapters.vda5050.mqtt.InProcessLink
import org.ktcs.adapters.vda5050.mqtt.MessageLink
import org.ktcs.adapters.vda5050.mqtt.MqttLink
import org.slf4j.LoggerFactory
import java.util.UUID
import java.util.concurrent.Executor
import java.util.concurrent.Executors
import java.util.concurrent.RejectedExecutionException

/**
 * kTCS's side of the MQTT traffic: one client connection shared by every VDA 5050 vehicle, and the embedded broker
 * when [settings] ask for it. Nothing starts until the first vehicle needs it, so a plant without VDA 5050 vehicles
 * pays nothing for the driver.
 *
 * With the builtin embedded broker, the driver is a [BuiltinBroker] link itself: no client. With the embedded HiveMQ,
 * the vehicles' messages and kTCS's orders take the [InProcessLink] inside the broker, and
 * the client carries only the `connection` topics (retained messages and last wills reach only a subscriber); with an
 * external broker the client carries everything.
 */
class Vda5050Broker(private val settings: BrokerSettings) : AutoCloseable {
    private val log = LoggerFactory.getLogger(Vda5050Broker::class.java)
    private var embedded: EmbeddedBroker? = null
    private var inProcess: InProcessLink? = null
    private var link: MqttLink? = null
    private var builtin: BuiltinBroker? = null

    @Volatile private var closed = false

    private val sender = lazy {
        Executors.newSingleThreadExecutor { Thread(it, SENDING_THREAD).apply { isDaemon = true } }
    }

    /**
     * Where the drivers' orders and instant actions are built, encoded and published: one thread for every vehicle, in
     * the order the drivers handed them over, so that the JSON and the broker's publishing cost the kernel thread
     * nothing. A message handed over after [close] is dropped.
     */
    val sending = Executor { task ->
        if (closed) {
            notSent()
        } else {
            try {
                sender.value.execute { sendGuarded(task) }
            } catch (_: RejectedExecutionException) {
                notSent()
            }
        }
    }

    private fun notSent() = log.debug("kTCS's MQTT side is closed: a message to a vehicle was not sent")

    private fun sendGuarded(task: Runnable) = try {
        task.run()
    } catch (error: RuntimeException) {
        log.warn("could not send a message to a vehicle: {}", error.toString())
    }

    /** What carries the vehicles' connection messages; connects (and starts the embedded broker) on first use. */
    @Synchronized
    fun connections(): MessageLink = builtin ?: link ?: start()

    /** What carries every other vehicle message, and orders and instant actions. */
    @Synchronized
    fun messages(): MessageLink {
        val connections = connections()
        return inProcess ?: connections
    }

    private fun start(): MessageLink {
        if (settings.isEmbedded && settings.implementation == EmbeddedBrokerKind.BUILTIN) {
            val config = BrokerConfig(
                settings.embeddedBindAddress,
                settings.embeddedPort,
                settings.username,
                settings.password,
                batchMillis = settings.embeddedBatchMillis,
            )
            return BuiltinBroker(config).also {
                it.start()
                builtin = it
            }
        }
        if (settings.isEmbedded) {
            val tap = InProcessLink()
            embedded = EmbeddedBroker(settings.embeddedBindAddress, settings.embeddedPort, tap.extension)
                .also { it.start() }
            inProcess = tap
        }
        val endpoint = settings.endpoint()
        val client = MqttLink("ktcs-${UUID.randomUUID()}", endpoint, settings.username, settings.password) { up ->
            if (up) log.info("connected to MQTT broker {}", endpoint) else log.warn("lost MQTT broker {}", endpoint)
        }
        client.connect()
        link = client
        return client
    }

    @Synchronized
    override fun close() {
        closed = true
        if (sender.isInitialized()) sender.value.shutdown()
        link?.close()
        link = null
        builtin?.close()
        builtin = null
        inProcess = null
        embedded?.close()
        embedded = null
    }

    companion object {
        /** The name of the thread that sends the vehicles' orders and instant actions. */
        const val SENDING_THREAD = "vda5050-send"
    }
}
