package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.delay
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.protocol.Vda
import kotlin.time.Duration.Companion.seconds

/**
 * Connection loss via the last will and recovery, pause and resume, immediate withdrawal (cancelOrder), a
 * schema-invalid message, and a vehicle error mid-order, with simulated vehicles over the embedded broker. Slower
 * vehicles (time factor 6) so the test can act mid-way.
 */
class Vda5050InstantActionsTest : FunSpec({
    val plant = VdaPlant(listOf("Point-0001", "Point-0027"), timeFactor = 6.0)
    val notifications = notificationsOf(plant.application.kernel)
    val driverLog = logLinesOf(Vda5050Driver::class.java.name)
    afterSpec { plant.close() }

    fun position() = plant.vehicle(0)["precisePosition"]?.toString()
    fun actionsSent() = plant.instantActions.flatMap { it.actions }.map { it.actionType }

    beforeSpec {
        eventually(20.seconds) {
            (0..1).forEach { plant.vehicle(it)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
        }
    }

    test("pausing the vehicle sends startPause and it stops; resuming sends stopPause and the order finishes") {
        plant.order("P1", "Storage 01", "Load cargo", plant.vehicleName(0))
        eventually(20.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "EXECUTING" }
        plant.put("/vehicles/${plant.vehicleName(0)}/paused?newValue=true")
        eventually(10.seconds) {
            actionsSent() shouldContain Vda.START_PAUSE
            plant.vehicle(0)["properties"]!!.jsonObject["vda5050:paused"]!!.jsonPrimitive.content shouldBe "true"
        }
        val stoppedAt = position()
        delay(1500)
        position() shouldBe stoppedAt
        plant.orderState("P1") shouldNotBe "FINISHED"

        plant.put("/vehicles/${plant.vehicleName(0)}/paused?newValue=false")
        eventually(10.seconds) { actionsSent() shouldContain Vda.STOP_PAUSE }
        eventually(60.seconds) { plant.orderState("P1") shouldBe "FINISHED" }
    }

    test("an immediate withdrawal sends cancelOrder; the vehicle stops and takes the next order") {
        plant.order("C1", "Goods out 01", "Unload cargo", plant.vehicleName(0))
        eventually(20.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "EXECUTING" }
        plant.post("/transportOrders/C1/withdrawal?immediate=true")
        eventually(10.seconds) { actionsSent() shouldContain Vda.CANCEL_ORDER }
        eventually(10.seconds) { plant.orderState("C1") shouldBe "FAILED" }
        eventually(10.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }

        plant.order("C2", "Goods out 01", "Unload cargo", plant.vehicleName(0))
        eventually(60.seconds) { plant.orderState("C2") shouldBe "FINISHED" }
    }

    test("a state message that breaks the schema is dropped with a log line naming the problem") {
        val before = driverLog.size
        plant.publishRaw("uagv/v2/kTCS/SIM-1/state", """{"headerId":1,"orderId":"x"}""")
        eventually(10.seconds) {
            val line = driverLog.drop(before).single { "invalid state message" in it }
            line shouldContain "required property 'timestamp' not found"
        }
        plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "IDLE" // the driver goes on
    }

    test("a fatal vehicle error mid-order fails the order with the vehicle's reason") {
        plant.order("E1", "Storage 01", "Load cargo", plant.vehicleName(0))
        eventually(20.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "EXECUTING" }
        plant.vehicles[0].raiseError("motorError", Vda.FATAL, "drive motor overheated")
        eventually(10.seconds) {
            plant.orderState("E1") shouldBe "FAILED"
            plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "ERROR"
        }
        val order = plant.get("/transportOrders/E1")
        order["properties"].toString() shouldContain "drive motor overheated"
        // The order's history says why it failed, in the vehicle's words.
        val history = order["history"]!!.jsonObject["entries"]!!.jsonArray.map { it.jsonObject }
        history.last()["eventCode"]!!.jsonPrimitive.content shouldBe "tcs:history:orderReachedFinalState"
        history.last()["supplements"]!!.jsonArray.single().jsonPrimitive.content shouldContain
            "the vehicle reported an error: FATAL motorError: drive motor overheated"
        notifications.any { "drive motor overheated" in it } shouldBe true

        plant.vehicles[0].clearErrors()
        eventually(10.seconds) { plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
    }

    // A vehicle that drops off the network mid-order (its connection cut, no DISCONNECT): the broker publishes its
    // last will, kTCS marks it UNKNOWN and tells the operator, the vehicle keeps its resources; once it is back, kTCS
    // resynchronises and the order finishes. Last, as the second vehicle then stands at a station.
    test("connection loss via the last will, and recovery") {
        val relay = TcpRelay(plant.brokerPort)
        try {
            plant.replaceVehicle(1, BrokerEndpoint("127.0.0.1", relay.port, tls = false))
            eventually(20.seconds) { plant.vehicle(1)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
            plant.order("L1", "Storage 02", "Load cargo", plant.vehicleName(1))
            eventually(20.seconds) { plant.vehicle(1)["state"]!!.jsonPrimitive.content shouldBe "EXECUTING" }
            val held = plant.vehicle(1)["allocatedResources"]!!.jsonArray.size

            relay.cut()
            eventually(20.seconds) { plant.vehicle(1)["state"]!!.jsonPrimitive.content shouldBe "UNKNOWN" }
            notifications.any { "CONNECTIONBROKEN" in it && "keeps its allocated resources" in it } shouldBe true
            (plant.vehicle(1)["allocatedResources"]!!.jsonArray.size > 0) shouldBe (held > 0)
            plant.orderState("L1") shouldBe "BEING_PROCESSED"

            relay.accepting = true // the vehicle's client reconnects by itself
            eventually(60.seconds) { plant.orderState("L1") shouldBe "FINISHED" }
        } finally {
            relay.close()
        }
    }
})
