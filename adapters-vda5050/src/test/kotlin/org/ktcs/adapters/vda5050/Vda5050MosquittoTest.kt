package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldBeStrictlyIncreasing
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.protocol.Vda
import kotlin.time.Duration.Companion.seconds

/**
 * The core of the suite against an external broker, Debian's Mosquitto: orders with updates and pick/drop, two
 * vehicles contending for paths, an immediate withdrawal, and connection loss via the last will with recovery.
 */
class Vda5050MosquittoTest : FunSpec({
    val mosquitto = Mosquitto.startOrSkip()
    if (mosquitto != null) {
        val plant = VdaPlant(listOf("Point-0001", "Point-0027"), brokerUrl = mosquitto.url, timeFactor = 8.0)
        val violations = exclusivityViolations(plant.application.kernel)
        afterSpec {
            plant.close()
            mosquitto.close()
        }

        test("orders with updates, pick and drop, and two vehicles contending: all finish, nothing allocated twice") {
            eventually(20.seconds) {
                (0..1).forEach { plant.vehicle(it)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
            }
            plant.order("M1", "Storage 01", "Load cargo", plant.vehicleName(0))
            plant.order("M2", "Storage 02", "Load cargo", plant.vehicleName(1))
            plant.order("M3", "Goods out 01", "Unload cargo", plant.vehicleName(0))
            plant.order("M4", "Goods out 02", "Unload cargo", plant.vehicleName(1))
            eventually(90.seconds) { (1..4).forEach { plant.orderState("M$it") shouldBe "FINISHED" } }
            violations.shouldBeEmpty()
            val sent = plant.orders.filter { it.serialNumber == "SIM-1" && it.orderId.startsWith("M1/") }
            sent.map { it.orderUpdateId }.shouldBeStrictlyIncreasing()
            sent.last().nodes.last { it.released }.actions.single().actionType shouldBe Vda.PICK
        }

        test("an immediate withdrawal sends cancelOrder through Mosquitto") {
            plant.order("M5", "Goods in south 01", "Load cargo", plant.vehicleName(0))
            eventually(20.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "EXECUTING" }
            plant.post("/transportOrders/M5/withdrawal?immediate=true")
            eventually(10.seconds) {
                plant.instantActions.flatMap { it.actions }.map { it.actionType } shouldContain Vda.CANCEL_ORDER
                plant.orderState("M5") shouldBe "FAILED"
            }
        }

        test("connection loss via Mosquitto's last will, and recovery") {
            val relay = TcpRelay(mosquitto.port)
            plant.replaceVehicle(1, BrokerEndpoint("127.0.0.1", relay.port, tls = false))
            try {
                eventually(20.seconds) { plant.vehicle(1)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
                relay.cut()
                eventually(30.seconds) { plant.vehicle(1)["state"]!!.jsonPrimitive.content shouldBe "UNKNOWN" }
                relay.accepting = true
                eventually(30.seconds) { plant.vehicle(1)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
            } finally {
                relay.close()
            }
        }
    }
})
