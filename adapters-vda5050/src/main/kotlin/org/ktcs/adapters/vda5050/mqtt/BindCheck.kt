package org.ktcs.adapters.vda5050.mqtt

import org.ktcs.extension.config.ConfigException
import java.io.IOException
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.ServerSocket
import java.net.UnknownHostException

/**
 * Whether the embedded MQTT broker can listen on an address and port, checked before it starts so that a bad setting
 * stops kTCS at start-up with one line naming the setting (either broker would otherwise report it its own way).
 */
internal object BindCheck {
    const val BIND_ADDRESS_KEY = "vda5050.embeddedBroker.bindAddress"
    const val PORT_KEY = "vda5050.embeddedBroker.port"

    /** Throws a [ConfigException] naming the setting to change if [bindAddress]:[port] cannot be listened on. */
    fun check(bindAddress: String, port: Int): InetAddress {
        val address = try {
            InetAddress.getByName(bindAddress)
        } catch (error: UnknownHostException) {
            throw ConfigException("$BIND_ADDRESS_KEY '$bindAddress' is not a known host or address: ${error.message}")
        }
        if (!canBind(address, 0)) {
            throw ConfigException(
                "$BIND_ADDRESS_KEY '$bindAddress' cannot be used: it is not an address of this machine " +
                    "(the embedded MQTT broker listens there; 127.0.0.1 for this machine, 0.0.0.0 for every interface)",
            )
        }
        if (!canBind(address, port)) {
            throw ConfigException(
                "$PORT_KEY $port cannot be used: the embedded MQTT broker cannot listen on $bindAddress:$port " +
                    "(in use or not allowed); choose a free port, or an external broker with vda5050.brokerUrl",
            )
        }
        return address
    }

    private fun canBind(address: InetAddress, port: Int): Boolean = try {
        ServerSocket().use { it.bind(InetSocketAddress(address, port), 1) }
        true
    } catch (_: IOException) {
        false
    }
}
