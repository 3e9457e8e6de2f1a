package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.ints.shouldBeLessThanOrEqual
import io.kotest.matchers.longs.shouldBeGreaterThanOrEqual
import io.kotest.matchers.longs.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import org.ktcs.adapters.vda5050.mqtt.InProcessLink
import org.ktcs.adapters.vda5050.mqtt.MqttLink
import org.ktcs.adapters.vda5050.protocol.AgvPosition
import org.ktcs.adapters.vda5050.protocol.BatteryState
import org.ktcs.adapters.vda5050.protocol.SafetyState
import org.ktcs.adapters.vda5050.protocol.State
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.adapters.vda5050.protocol.Vda5050Json
import org.ktcs.adapters.vda5050.protocol.Visualization
import java.time.Instant
import java.util.Collections
import kotlin.time.Duration.Companion.seconds

private const val PREFIX = "uagv/v2/kTCS/SIM-1"
private const val INTERVAL_MILLIS = 200L

private fun pose(i: Int) = AgvPosition(i / 10.0, 0.0, 0.0, "map", positionInitialized = true)

private fun stateJson(headerId: Int) = Vda5050Json.encodeToString(
    State.serializer(),
    State(
        headerId.toLong(), Instant.now().toString(), Vda.PROTOCOL_VERSION, "kTCS", "SIM-1", "", 0, "Point-0001", 0,
        emptyList(), emptyList(), false, emptyList(), BatteryState(80.0, false), "AUTOMATIC", emptyList(),
        SafetyState("NONE", false), agvPosition = pose(headerId),
    ),
).toByteArray()

private fun visualizationJson(headerId: Int) = Vda5050Json.encodeToString(
    Visualization.serializer(),
    Visualization(headerId.toLong(), Instant.now().toString(), Vda.PROTOCOL_VERSION, "kTCS", "SIM-1", pose(headerId)),
).toByteArray()

/**
 * With the embedded broker, a vehicle's state messages come through kTCS's MQTT client (every one, in order), and
 * its visualization messages through the in-process link, whose interceptor the vehicle's client carries only from
 * the moment the next one is due (`minVisualizationInterval`) until one is taken: most of them never reach HiveMQ's
 * extension executor, and none within the interval reaches the driver. A vehicle that reconnects is heard again.
 */
class SampledVisualizationTest : FunSpec({
    val port = freePort()
    val broker = Vda5050Broker(BrokerSettings(embeddedPort = port))
    afterSpec { broker.close() }

    test("every state message arrives in order; visualization is sampled before HiveMQ's hop") {
        val properties = Vda5050Properties.read(
            "Vehicle-01",
            vdaProperties("SIM-1") + ("vda5050:minVisualizationInterval" to "$INTERVAL_MILLIS"),
        )
        val topics = VehicleTopics("Vehicle-01", properties, broker::messages, broker::subscriptions)
        val states = Collections.synchronizedList(mutableListOf<Long>())
        val poses = Collections.synchronizedList(mutableListOf<Long>())
        topics.listen { message ->
            when (message) {
                is State -> states += message.headerId
                is Visualization -> poses += System.currentTimeMillis()
            }
        }
        val link = broker.messages().shouldBeInstanceOf<InProcessLink>()
        val relay = TcpRelay(port)
        val vehicle = MqttLink("vehicle-sampled", BrokerEndpoint("127.0.0.1", relay.port, tls = false))
        try {
            vehicle.connect()
            eventually(5.seconds) {
                // kTCS's subscription is in place
                vehicle.publish("$PREFIX/state", stateJson(0), 0).get()
                states.isEmpty() shouldBe false
            }
            eventually(5.seconds) { link.tappedClients shouldBeGreaterThanOrEqual 1 } // learning: tapped
            Thread.sleep(INTERVAL_MILLIS)
            states.clear()
            poses.clear()
            val interceptedBefore = link.intercepted.get()
            val start = System.currentTimeMillis()
            // 2 s of a vehicle that sends state at 50 Hz and visualization at 100 Hz.
            for (i in 0 until 200) {
                if (i % 2 == 0) vehicle.publish("$PREFIX/state", stateJson(1 + i / 2), 0)
                vehicle.publish("$PREFIX/visualization", visualizationJson(i), 0)
                Thread.sleep(10)
            }
            val elapsed = System.currentTimeMillis() - start
            eventually(10.seconds) { states.toList() shouldContainExactly (1L..100L).toList() }
            val taken = poses.toList()
            taken.size shouldBeGreaterThanOrEqual 2
            taken.size shouldBeLessThanOrEqual (elapsed / INTERVAL_MILLIS + 2).toInt()
            taken.zipWithNext { a, b -> b - a }.forEach { it shouldBeGreaterThanOrEqual INTERVAL_MILLIS }
            // Without sampling, all 300 messages would pass the interceptor; with it, about one per interval and the
            // few the vehicle publishes between the due time and the next visualization.
            link.intercepted.get() - interceptedBefore shouldBeLessThan 60L

            relay.cut() // the vehicle drops out and comes back: its new connection is tapped again
            relay.accepting = true
            eventually(20.seconds) { vehicle.isConnected shouldBe true }
            val before = poses.size
            eventually(10.seconds) {
                vehicle.publish("$PREFIX/visualization", visualizationJson(0), 0).get()
                poses.size shouldBeGreaterThanOrEqual before + 1
            }
        } finally {
            vehicle.close()
            relay.close()
            topics.stopListening()
        }
    }

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
