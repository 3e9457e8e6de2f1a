package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import kotlin.time.Duration.Companion.seconds

/**
 * A vehicle that drops off the network mid-order (its connection cut, no DISCONNECT): the broker publishes its last
 * will, kTCS marks it UNKNOWN and tells the operator, the vehicle keeps its resources; once it is back, kTCS
 * resynchronises and the order finishes.
 */
class Vda5050ConnectionTest : FunSpec({
    val plant = VdaPlant(listOf("Point-0001"), timeFactor = 5.0, simulateLater = true)
    afterSpec { plant.close() }

    test("connection loss via the last will, and recovery") {
        val relay = TcpRelay(plant.brokerPort)
        val notifications = notificationsOf(plant.application.kernel)
        val vehicle = plant.simulated(0, "Point-0001", BrokerEndpoint("127.0.0.1", relay.port, tls = false))
        try {
            eventually(20.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
            plant.order("L1", "Storage 01", "Load cargo")
            eventually(20.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "EXECUTING" }
            val held = plant.vehicle(0)["allocatedResources"]!!.jsonArray.size

            relay.cut()
            eventually(30.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "UNKNOWN" }
            notifications.any { "CONNECTIONBROKEN" in it && "keeps its allocated resources" in it } shouldBe true
            (plant.vehicle(0)["allocatedResources"]!!.jsonArray.size > 0) shouldBe (held > 0)
            plant.orderState("L1") shouldBe "BEING_PROCESSED"

            relay.accepting = true // the vehicle's client reconnects by itself
            eventually(60.seconds) { plant.orderState("L1") shouldBe "FINISHED" }
        } finally {
            vehicle.close()
            relay.close()
        }
    }
})
