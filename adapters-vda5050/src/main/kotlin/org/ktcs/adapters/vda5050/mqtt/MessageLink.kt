package org.ktcs.adapters.vda5050.mqtt

import java.nio.ByteBuffer

/**
 * How the driver hears its vehicles and reaches them: kTCS's MQTT client ([MqttLink]) for an external broker, or the
 * embedded broker itself ([InProcessLink]) when it runs in kTCS's process.
 */
interface MessageLink {
    /**
     * Hands [handler] the payload of every message on [topic] (one exact topic, no wildcards), on the link's threads.
     * The buffer is read-only and valid only during the call: a message the handler declines costs no copy.
     */
    fun listen(topic: String, qos: Int, handler: (ByteBuffer) -> Unit)

    fun stopListening(topic: String)

    fun send(topic: String, payload: ByteArray, qos: Int)

    companion object {
        /** The payload of a message without one. */
        val EMPTY_PAYLOAD: ByteBuffer = ByteBuffer.allocate(0).asReadOnlyBuffer()
    }
}
