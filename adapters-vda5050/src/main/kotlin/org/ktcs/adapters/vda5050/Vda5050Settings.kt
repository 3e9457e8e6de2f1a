package org.ktcs.adapters.vda5050

import org.ktcs.extension.config.Setting
import org.ktcs.extension.config.intSetting
import org.ktcs.extension.config.stringSetting

/**
 * The VDA 5050 driver's broker settings (`vda5050.*`), declared by [Vda5050Extension] so that the configuration
 * reference and `config/ktcs.conf` list them.
 */
object Vda5050Settings {
    val brokerUrl = stringSetting(
        "vda5050.brokerUrl",
        "embedded",
        "The MQTT broker of the VDA 5050 vehicles: 'embedded' (kTCS starts its own, only when a vehicle uses the " +
            "VDA 5050 driver) or an external broker's URL, e.g. tcp://host:1883 or ssl://host:8883.",
    )
    val embeddedBindAddress = stringSetting(
        "vda5050.embeddedBroker.bindAddress",
        "127.0.0.1",
        "The address the embedded MQTT broker listens on (0.0.0.0: every interface, for vehicles on the network).",
    )
    val embeddedPort = intSetting(
        "vda5050.embeddedBroker.port",
        1883,
        1..65535,
        "The port the embedded MQTT broker listens on.",
    )
    val username = stringSetting(
        "vda5050.username",
        "",
        "The user name kTCS gives the MQTT broker (empty: none).",
    )
    val password = stringSetting(
        "vda5050.password",
        "",
        "The password kTCS gives the MQTT broker, with vda5050.username.",
    )
    val mapId = stringSetting(
        "vda5050.mapId",
        "",
        "The mapId of the nodes in VDA 5050 orders unless a point or vehicle sets vda5050:mapId.",
    )

    val all: List<Setting<*>> = listOf(brokerUrl, embeddedBindAddress, embeddedPort, username, password, mapId)
}
