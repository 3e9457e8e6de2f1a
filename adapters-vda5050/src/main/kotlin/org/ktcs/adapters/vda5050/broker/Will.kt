package org.ktcs.adapters.vda5050.broker

import io.netty.handler.codec.mqtt.MqttConnectMessage

/**
 * A client's last will: published for it when its connection ends without a DISCONNECT (dropped, silent past its
 * keep-alive, taken over, or closed for a protocol error). MQTT 5's will delay interval is not supported: the will
 * goes out at once.
 */
internal class Will(val topic: String, val payload: ByteArray, val qos: Int, val retain: Boolean) {
    companion object {
        /** The will [connect] carries, if any. */
        fun of(connect: MqttConnectMessage): Will? {
            val header = connect.variableHeader()
            if (!header.isWillFlag) return null
            val payload = connect.payload()
            return Will(
                payload.willTopic(),
                payload.willMessageInBytes() ?: ByteArray(0),
                header.willQos(),
                header.isWillRetain,
            )
        }

        /** MQTT 5's DISCONNECT reason code that asks for the will all the same. */
        const val DISCONNECT_WITH_WILL: Byte = 0x04
    }
}
