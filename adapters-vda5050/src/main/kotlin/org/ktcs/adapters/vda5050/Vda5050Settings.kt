package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.broker.BrokerConfig
import org.ktcs.adapters.vda5050.mqtt.EmbeddedBrokerKind
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
    val embeddedImplementation = Setting(
        "vda5050.embeddedBroker.implementation",
        EmbeddedBrokerKind.BUILTIN,
        "Which embedded MQTT broker kTCS starts: 'builtin' (its own, on Netty: the driver hears the vehicles on the " +
            "broker's thread) or 'hivemq' (HiveMQ Community Edition).",
        EmbeddedBrokerKind::of,
    )
    val embeddedBatchMillis = intSetting(
        "vda5050.embeddedBroker.batchMillis",
        BrokerConfig.DEFAULT_BATCH_MILLIS.toInt(),
        0..50,
        "How many milliseconds the builtin embedded broker's thread pauses after each round of work, so that the " +
            "messages arriving meanwhile are read in one round (0: every message wakes it on its own). Saves CPU " +
            "with many vehicles; a message waits at most this long.",
    )
    val username = stringSetting(
        "vda5050.username",
        "",
        "The user name kTCS gives an external MQTT broker, and the one the builtin embedded broker asks of every " +
            "client (empty: none).",
    )
    val password = stringSetting(
        "vda5050.password",
        "",
        "The password that goes with vda5050.username (given to an external broker, asked by the builtin one).",
    )
    val mapId = stringSetting(
        "vda5050.mapId",
        "",
        "The mapId of the nodes in VDA 5050 orders unless a point or vehicle sets vda5050:mapId.",
    )

    val all: List<Setting<*>> = listOf(
        brokerUrl,
        embeddedBindAddress,
        embeddedPort,
        embeddedImplementation,
        embeddedBatchMillis,
        username,
        password,
        mapId,
    )
}
