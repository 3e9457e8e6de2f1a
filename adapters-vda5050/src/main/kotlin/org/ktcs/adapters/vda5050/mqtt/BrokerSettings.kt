package org.ktcs.adapters.vda5050.mqtt

import org.ktcs.adapters.vda5050.broker.BrokerConfig
import java.net.URI

/**
 * Where the VDA 5050 vehicles' MQTT broker is: [url] `embedded` (kTCS starts its own broker on
 * [embeddedBindAddress]:[embeddedPort], the [implementation] chosen) or `tcp://host:port` / `ssl://host:port` for an external one.
 */
data class BrokerSettings(
    val url: String = EMBEDDED,
    val embeddedBindAddress: String = "127.0.0.1",
    val embeddedPort: Int = 1883,
    val username: String = "",
    val password: String = "",
    val mapId: String = "",
    val implementation: EmbeddedBrokerKind = EmbeddedBrokerKind.BUILTIN,
    val embeddedBatchMillis: Long = BrokerConfig.DEFAULT_BATCH_MILLIS,
) {
    val isEmbedded: Boolean get() = url.trim().equals(EMBEDDED, ignoreCase = true)

    /** The address clients connect to. */
    fun endpoint(): BrokerEndpoint {
        if (isEmbedded) {
            val host = embeddedBindAddress.takeUnless { it == "0.0.0.0" || it == "::" } ?: "127.0.0.1"
            return BrokerEndpoint(host, embeddedPort, tls = false)
        }
        val uri = try {
            URI(url.trim())
        } catch (error: java.net.URISyntaxException) {
            throw IllegalArgumentException("vda5050.brokerUrl '$url' is not a URL: ${error.reason}")
        }
        val tls = when (uri.scheme?.lowercase()) {
            "tcp", "mqtt" -> false

            "ssl", "tls", "mqtts" -> true

            else -> throw IllegalArgumentException(
                "vda5050.brokerUrl '$url' must be 'embedded' or start with tcp://, mqtt://, ssl:// or mqtts://",
            )
        }
        require(!uri.host.isNullOrBlank()) { "vda5050.brokerUrl '$url' names no host" }
        val port = if (uri.port > 0) {
            uri.port
        } else if (tls) {
            8883
        } else {
            1883
        }
        return BrokerEndpoint(uri.host, port, tls)
    }

    companion object {
        const val EMBEDDED = "embedded"
    }
}

/** A broker's host and port, and whether to speak TLS to it. */
data class BrokerEndpoint(val host: String, val port: Int, val tls: Boolean) {
    override fun toString(): String = "${if (tls) "ssl" else "tcp"}://$host:$port"
}

/** Which embedded broker kTCS starts: its own ([BUILTIN]) or HiveMQ Community Edition. */
enum class EmbeddedBrokerKind(private val text: String) {
    BUILTIN("builtin"),
    HIVEMQ("hivemq"),
    ;

    override fun toString(): String = text

    companion object {
        /** The kind written [text] (case ignored), or null. */
        fun of(text: String): EmbeddedBrokerKind? = entries.firstOrNull { it.text.equals(text, ignoreCase = true) }
    }
}
