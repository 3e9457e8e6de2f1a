package org.ktcs.adapters.vda5050.mqtt

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.core.spec.style.scopes.FunSpecContainerScope
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeInstanceOf
import org.ktcs.adapters.vda5050.TcpRelay
import org.ktcs.adapters.vda5050.Vda5050Broker
import org.ktcs.adapters.vda5050.broker.BuiltinBroker
import org.ktcs.adapters.vda5050.freePort
import java.nio.ByteBuffer
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

/**
 * With either embedded broker, the driver hears the vehicles inside the broker and publishes through it: a vehicle's
 * messages (a retained one too) reach it without a second MQTT client decoding them, its messages reach the vehicle,
 * other subscribers still get everything, and the `connection` topic with the broker's last will reaches it (through
 * kTCS's client with HiveMQ, from the builtin broker itself).
 */
class InProcessLinkTest : FunSpec({
    EmbeddedBrokerKind.entries.forEach { kind ->
        val port = freePort()
        val broker = Vda5050Broker(BrokerSettings(embeddedPort = port, implementation = kind))
        afterSpec { broker.close() }
        context("the $kind broker") { inProcessLinkTests(kind, broker, port) }
    }
})

private suspend fun FunSpecContainerScope.inProcessLinkTests(
    kind: EmbeddedBrokerKind,
    broker: Vda5050Broker,
    port: Int,
) {
    val endpoint = BrokerEndpoint("127.0.0.1", port, tls = false)

    fun text(payload: ByteBuffer) = Charsets.UTF_8.decode(payload).toString()
    fun recorder() = Collections.synchronizedList(mutableListOf<Pair<String, String>>())

    test("the vehicle's messages reach the driver in the broker, and other subscribers too") {
        if (kind == EmbeddedBrokerKind.HIVEMQ) {
            broker.messages().shouldBeInstanceOf<InProcessLink>()
        } else {
            broker.messages().shouldBeInstanceOf<BuiltinBroker>()
            broker.connections().shouldBeInstanceOf<BuiltinBroker>()
        }
        val vehicle = MqttLink("vehicle-1", endpoint).apply { connect() }
        val other = MqttLink("other", endpoint).apply { connect() }
        vehicle.publish("v/1/factsheet", "factsheet".toByteArray(), 1, retain = true).get()
        val heard = recorder()
        val otherHeard = Collections.synchronizedList(mutableListOf<String>())
        other.subscribe("v/1/state", 0) { otherHeard += String(it) }.get()
        listOf("state", "visualization", "factsheet").forEach { topic ->
            broker.messages().listen("v/1/$topic", 0) { heard += topic to text(it) }
        }
        vehicle.publish("v/1/state", "state 1".toByteArray(), 0).get()
        vehicle.publish("v/1/visualization", "pose".toByteArray(), 0).get()
        eventually(5.seconds) {
            // The retained factsheet comes from the broker's store, in no set order with the live messages.
            heard.toList() shouldContainExactlyInAnyOrder listOf(
                "factsheet" to "factsheet", // retained before the driver listened
                "state" to "state 1",
                "visualization" to "pose",
            )
            otherHeard.toList() shouldContainExactly listOf("state 1")
        }
        broker.messages().stopListening("v/1/state")
        vehicle.publish("v/1/state", "state 2".toByteArray(), 0).get()
        eventually(5.seconds) { otherHeard.toList() shouldContainExactly listOf("state 1", "state 2") }
        heard.count { it.first == "state" } shouldBe 1
        vehicle.close()
        other.close()
    }

    test("orders and instant actions reach the vehicle through the broker") {
        val vehicle = MqttLink("vehicle-2", endpoint).apply { connect() }
        val received = recorder()
        listOf("order", "instantActions").forEach { topic ->
            vehicle.subscribe("v/2/$topic", 1) { received += topic to String(it) }.get()
        }
        broker.messages().send("v/2/order", "an order".toByteArray(), 0)
        broker.messages().send("v/2/instantActions", "a cancelOrder".toByteArray(), 1)
        eventually(5.seconds) {
            received.toSet() shouldBe setOf("order" to "an order", "instantActions" to "a cancelOrder")
        }
        vehicle.close()
    }

    test("a vehicle that drops out: its last will on the connection topic reaches the driver") {
        val relay = TcpRelay(endpoint.port)
        val heard = Collections.synchronizedList(mutableListOf<String>())
        broker.connections().listen("v/3/connection", 1) { heard += text(it) }
        val vehicle = MqttLink(
            "vehicle-3",
            BrokerEndpoint("127.0.0.1", relay.port, tls = false),
            will = LastWill("v/3/connection", "CONNECTIONBROKEN".toByteArray()),
        )
        try {
            vehicle.connect()
            vehicle.publish("v/3/connection", "ONLINE".toByteArray(), 1, retain = true).get()
            eventually(5.seconds) { heard.toList() shouldContainExactly listOf("ONLINE") }
            relay.accepting = false
            relay.cut()
            eventually(20.seconds) { heard.last() shouldContain "CONNECTIONBROKEN" }
        } finally {
            vehicle.close()
            relay.close()
        }
    }
}
