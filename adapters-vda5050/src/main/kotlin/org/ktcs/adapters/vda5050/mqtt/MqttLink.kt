package org.ktcs.adapters.vda5050.mqtt

import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3AsyncClient
import org.slf4j.LoggerFactory
import java.nio.ByteBuffer
import java.util.concurrent.CompletableFuture
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit

/** A message the broker keeps for a client that drops out: its MQTT last will. */
class LastWill(val topic: String, val payload: ByteArray, val qos: Int = 1, val retain: Boolean = true)

/**
 * One MQTT 3.1.1 connection (HiveMQ MQTT client) that reconnects by itself (after 0.5 s, backing off to at most 5 s)
 * and subscribes again after a reconnect.
 * Callbacks run on the client's threads. [onConnectionChange] hears `true` on every (re)connect, `false` on a loss.
 */
class MqttLink(
    private val clientId: String,
    private val endpoint: BrokerEndpoint,
    private val username: String = "",
    private val password: String = "",
    private val will: LastWill? = null,
    private val onConnectionChange: (Boolean) -> Unit = {},
) : MessageLink, AutoCloseable {
    private val log = LoggerFactory.getLogger(MqttLink::class.java)
    private val handlers = ConcurrentHashMap<String, (ByteBuffer) -> Unit>()

    @Volatile private var closed = false

    private val client: Mqtt3AsyncClient = MqttClient.builder()
        .useMqttVersion3()
        .identifier(clientId)
        .serverHost(endpoint.host)
        .serverPort(endpoint.port)
        .let { if (endpoint.tls) it.sslWithDefaultConfig() else it }
        // The client's default backs off to 2 minutes; a fleet manager (and a vehicle) should be back within seconds
        // of its broker (or network) returning.
        .automaticReconnect()
        .initialDelay(RECONNECT_INITIAL_MILLIS, TimeUnit.MILLISECONDS)
        .maxDelay(RECONNECT_MAX_SECONDS, TimeUnit.SECONDS)
        .applyAutomaticReconnect()
        .addConnectedListener { onConnectionChange(true) }
        .addDisconnectedListener { context ->
            if (!closed) {
                log.debug("MQTT client {} lost {}: {}", clientId, endpoint, context.cause.message)
                onConnectionChange(false)
            }
        }
        .buildAsync()

    val isConnected: Boolean get() = client.state.isConnected

    /** Connects; waits at most [timeoutSeconds] for the first connection (the client keeps trying afterwards). */
    fun connect(timeoutSeconds: Long = 10): Boolean {
        var connect = client.connectWith().cleanSession(true).keepAlive(KEEP_ALIVE_SECONDS)
        if (username.isNotEmpty()) {
            connect = connect.simpleAuth().username(username).password(password.toByteArray()).applySimpleAuth()
        }
        if (will != null) {
            connect = connect.willPublish().topic(will.topic).payload(will.payload).qos(qos(will.qos))
                .retain(will.retain).applyWillPublish()
        }
        return runCatching { connect.send().get(timeoutSeconds, TimeUnit.SECONDS) }
            .onFailure { log.warn("MQTT client {} cannot connect to {} yet: {}", clientId, endpoint, it.message) }
            .isSuccess
    }

    fun subscribe(topic: String, qos: Int, handler: (ByteArray) -> Unit): CompletableFuture<*> =
        subscribeBuffers(topic, qos) { payload -> handler(ByteArray(payload.remaining()).also(payload::get)) }

    private fun subscribeBuffers(topic: String, qos: Int, handler: (ByteBuffer) -> Unit): CompletableFuture<*> {
        handlers[topic] = handler
        return client.subscribeWith().topicFilter(topic).qos(qos(qos))
            .callback { publish -> handlers[topic]?.invoke(publish.payload.orElse(MessageLink.EMPTY_PAYLOAD)) }
            .send()
    }

    fun unsubscribe(topic: String) {
        handlers.remove(topic)
        client.unsubscribeWith().topicFilter(topic).send()
    }

    override fun listen(topic: String, qos: Int, handler: (ByteBuffer) -> Unit) {
        subscribeBuffers(topic, qos, handler)
    }

    override fun stopListening(topic: String) = unsubscribe(topic)

    override fun send(topic: String, payload: ByteArray, qos: Int) {
        publish(topic, payload, qos)
    }

    fun publish(topic: String, payload: ByteArray, qos: Int, retain: Boolean = false): CompletableFuture<*> =
        client.publishWith().topic(topic).payload(payload).qos(qos(qos)).retain(retain).send()

    /** Disconnects cleanly: the broker does not publish the last will. */
    override fun close() {
        closed = true
        runCatching { client.disconnect().get(CLOSE_SECONDS, TimeUnit.SECONDS) }
    }

    private fun qos(code: Int): MqttQos = MqttQos.fromCode(code) ?: MqttQos.AT_MOST_ONCE

    private companion object {
        const val KEEP_ALIVE_SECONDS = 10
        const val CLOSE_SECONDS = 5L
        const val RECONNECT_INITIAL_MILLIS = 500L
        const val RECONNECT_MAX_SECONDS = 5L
    }
}
