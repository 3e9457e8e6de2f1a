package org.ktcs.adapters.vda5050.broker

import io.netty.handler.codec.mqtt.MqttConnectMessage
import io.netty.handler.codec.mqtt.MqttConnectReturnCode
import io.netty.handler.codec.mqtt.MqttVersion

/** Whether the broker accepts a CONNECT, and if not the return code (MQTT 3.1.1) or reason code (MQTT 5) it answers. */
internal object ConnectAnswer {
    /** The refusal for [connect], or null if it is accepted; [username] empty: any client may connect. */
    fun refusal(connect: MqttConnectMessage, username: String, password: String): MqttConnectReturnCode? {
        val v5 = connect.variableHeader().version() == MqttVersion.MQTT_5.protocolLevel().toInt()
        val payload = connect.payload()
        val clientId = payload.clientIdentifier().orEmpty()
        val persistent = !connect.variableHeader().isCleanSession
        return when {
            username.isNotEmpty() && !credentialsMatch(connect, username, password) ->
                if (v5) {
                    MqttConnectReturnCode.CONNECTION_REFUSED_BAD_USERNAME_OR_PASSWORD
                } else {
                    MqttConnectReturnCode.CONNECTION_REFUSED_BAD_USER_NAME_OR_PASSWORD
                }

            // MQTT 3.1.1 gives an empty client id a session only if it is a clean one (MQTT 5 assigns an id).
            clientId.isEmpty() && persistent && !v5 -> MqttConnectReturnCode.CONNECTION_REFUSED_IDENTIFIER_REJECTED

            else -> null
        }
    }

    /** The refusal of a CONNECT that named a protocol the broker does not speak. */
    fun unsupportedProtocol(v5: Boolean): MqttConnectReturnCode = if (v5) {
        MqttConnectReturnCode.CONNECTION_REFUSED_UNSUPPORTED_PROTOCOL_VERSION
    } else {
        MqttConnectReturnCode.CONNECTION_REFUSED_UNACCEPTABLE_PROTOCOL_VERSION
    }

    /** The refusal of a CONNECT whose client id the codec rejected. */
    fun badClientId(v5: Boolean): MqttConnectReturnCode = if (v5) {
        MqttConnectReturnCode.CONNECTION_REFUSED_CLIENT_IDENTIFIER_NOT_VALID
    } else {
        MqttConnectReturnCode.CONNECTION_REFUSED_IDENTIFIER_REJECTED
    }

    private fun credentialsMatch(connect: MqttConnectMessage, username: String, password: String): Boolean {
        val header = connect.variableHeader()
        val payload = connect.payload()
        return header.hasUserName() && payload.userName() == username &&
            (
                password.isEmpty() || (
                    header.hasPassword() && payload.passwordInBytes().contentEquals(
                        password.toByteArray(),
                    )
                    )
                )
    }
}
