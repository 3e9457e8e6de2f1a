package org.ktcs.adapters.vda5050.broker

import io.netty.buffer.ByteBuf
import io.netty.channel.embedded.EmbeddedChannel
import io.netty.handler.codec.mqtt.MqttEncoder
import io.netty.handler.codec.mqtt.MqttMessage
import io.netty.handler.codec.mqtt.MqttMessageBuilders
import io.netty.handler.codec.mqtt.MqttQoS
import io.netty.handler.codec.mqtt.MqttVersion
import java.io.InputStream
import java.net.Socket
import java.net.SocketTimeoutException

/** A client that writes whatever bytes a test wants, malformed ones too, and reads the broker's answer raw. */
class RawClient(port: Int) : AutoCloseable {
    private val socket = Socket("127.0.0.1", port).apply { soTimeout = READ_TIMEOUT_MILLIS }
    private val input: InputStream = socket.getInputStream()

    fun write(bytes: ByteArray) {
        socket.getOutputStream().apply {
            write(bytes)
            flush()
        }
    }

    fun write(message: MqttMessage) = write(encode(message))

    /** The next [count] bytes the broker sent. */
    fun read(count: Int): ByteArray = input.readNBytes(count)

    /** Whether the broker closed the connection within the read timeout (reading and dropping what came first). */
    fun closedByBroker(): Boolean = try {
        while (input.read() >= 0) Unit
        true
    } catch (_: SocketTimeoutException) {
        false
    } catch (_: java.io.IOException) {
        true
    }

    override fun close() = socket.close()

    companion object {
        const val READ_TIMEOUT_MILLIS = 5000

        /** [message] as MQTT 3.1.1 bytes. */
        fun encode(message: MqttMessage): ByteArray {
            val channel = EmbeddedChannel(MqttEncoder.INSTANCE)
            channel.writeOutbound(message)
            val buffer = channel.readOutbound<ByteBuf>()
            return ByteArray(buffer.readableBytes()).also { buffer.readBytes(it) }.also { buffer.release() }
        }

        /** An MQTT 3.1.1 CONNECT. */
        fun connect(
            clientId: String,
            keepAliveSeconds: Int = 0,
            cleanSession: Boolean = true,
            willTopic: String? = null,
            will: String = "",
        ): MqttMessage {
            val builder = MqttMessageBuilders.connect().protocolVersion(MqttVersion.MQTT_3_1_1).clientId(clientId)
                .cleanSession(cleanSession).keepAlive(keepAliveSeconds)
            if (willTopic != null) {
                builder.willFlag(true).willTopic(willTopic).willMessage(will.toByteArray())
                    .willQoS(MqttQoS.AT_LEAST_ONCE).willRetain(true)
            }
            return builder.build()
        }
    }
}
