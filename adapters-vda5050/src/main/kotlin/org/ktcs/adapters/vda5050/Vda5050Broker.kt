package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import org.ktcs.adapters.vda5050.mqtt.EmbeddedBroker
import org.ktcs.adapters.vda5050.mqtt.MqttLink
import org.slf4j.LoggerFactory
import java.util.UUID

/**
 * kTCS's side of the MQTT traffic: one client connection shared by every VDA 5050 vehicle, and the embedded broker
 * when [settings] ask for it. Nothing starts until the first vehicle needs it, so a plant without VDA 5050 vehicles
 * pays nothing for the driver.
 */
class Vda5050Broker(private val settings: BrokerSettings) : AutoCloseable {
    private val log = LoggerFactory.getLogger(Vda5050Broker::class.java)
    private var embedded: EmbeddedBroker? = null
    private var link: MqttLink? = null

    /** The shared client, connecting (and starting the embedded broker) on first use. */
    @Synchronized
    fun link(): MqttLink = link ?: start()

    private fun start(): MqttLink {
        if (settings.isEmbedded) {
            embedded = EmbeddedBroker(settings.embeddedBindAddress, settings.embeddedPort).also { it.start() }
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
        link?.close()
        link = null
        embedded?.close()
        embedded = null
    }
}
