package org.ktcs.adapters.vda5050.mqtt

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.vda5050.TcpRelay
import org.ktcs.adapters.vda5050.Vda5050Broker
import org.ktcs.adapters.vda5050.freePort
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

/** kTCS's MQTT client (the vehicles' connection topics, and every topic with an external broker) after a lost broker. */
class MqttLinkTest : FunSpec({
    val port = freePort()
    val broker = Vda5050Broker(BrokerSettings(embeddedPort = port))
    beforeSpec { broker.connections() }
    afterSpec { broker.close() }

    test("kTCS's client subscribes again after it lost the broker") {
        val relay = TcpRelay(port)
        val client = MqttLink("ktcs-resubscribe", BrokerEndpoint("127.0.0.1", relay.port, tls = false))
        val vehicle = MqttLink("vehicle-resubscribe", BrokerEndpoint("127.0.0.1", port, tls = false))
        val heard = Collections.synchronizedList(mutableListOf<String>())
        try {
            client.connect()
            vehicle.connect()
            client.subscribe("v/9/state", 1) { heard += String(it) }.get()
            vehicle.publish("v/9/state", "before".toByteArray(), 0).get()
            eventually(5.seconds) { heard.toList() shouldContainExactly listOf("before") }
            relay.cut()
            eventually(5.seconds) { client.isConnected shouldBe false }
            relay.accepting = true
            eventually(20.seconds) { client.isConnected shouldBe true }
            eventually(10.seconds) {
                vehicle.publish("v/9/state", "after".toByteArray(), 0).get()
                heard.last() shouldBe "after"
            }
        } finally {
            client.close()
            vehicle.close()
            relay.close()
        }
    }
})
