package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldBeStrictlyIncreasing
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.jsonPrimitive
import kotlinx.serialization.json.long
import org.ktcs.adapters.vda5050.protocol.Vda
import org.ktcs.api.model.LoadHandlingDevice
import kotlin.time.Duration.Companion.seconds

/**
 * VDA 5050 vehicles played by the simulator over kTCS's embedded broker, driven by kTCS through real orders: one
 * vehicle's orders with updates, pick and drop; then both sent along the same paths, crossing each other's way.
 */
class Vda5050OrderTest : FunSpec({
    val plant = VdaPlant(
        listOf("Point-0001", "Point-0027"),
        vehicleProperties = mapOf("vda5050:vehicleLengthLoaded" to "1500", "vda5050:vehicleLengthUnloaded" to "900"),
        timeFactor = 16.0, // nothing here acts mid-way
    )
    val violations = exclusivityViolations(plant.application.kernel)
    fun length() = plant.vehicle(0)["length"]!!.jsonPrimitive.long
    afterSpec { plant.close() }

    test("the vehicle comes online and reports its position") {
        eventually(20.seconds) {
            plant.vehicle(0)["currentPosition"]!!.jsonPrimitive.content shouldBe "Point-0001"
            plant.vehicle(0)["state"]!!.jsonPrimitive.content shouldBe "IDLE"
            length() shouldBe 900L // vda5050:vehicleLengthUnloaded, not the plant model's 1000
        }
    }

    test("an order goes out as base and horizon, grows by order updates, and finishes after the pick") {
        plant.order("T1", "Storage 01", "Load cargo", plant.vehicleName(0))
        eventually(60.seconds) { plant.orderState("T1") shouldBe "FINISHED" }

        val sent = plant.orders.filter { it.serialNumber == "SIM-1" }
        sent.map { it.orderId }.toSet().size shouldBe 1
        sent.map { it.orderUpdateId }.shouldBeStrictlyIncreasing()
        sent.size shouldBeGreaterThan 1
        // The first message releases one step (the next waits for the vehicle to confirm it), the rest is horizon.
        val first = sent.first()
        first.edges.count { it.released } shouldBe 1
        first.nodes.any { !it.released } shouldBe true
        // Every update starts at the last released node of the one before (the stitching node).
        sent.zipWithNext().forEach { (before, after) ->
            after.nodes.first().nodeId shouldBe before.nodes.last { it.released }.nodeId
            after.nodes.first().sequenceId shouldBe before.nodes.last { it.released }.sequenceId
        }
        // Positions in metres: the demo's Point-0001 is at (31000 mm, 11000 mm).
        first.nodes.first().nodePosition!!.x shouldBe 31.0
        first.nodes.first().nodePosition!!.y shouldBe 11.0
        val pick = sent.last().nodes.last { it.released }.actions.single()
        pick.actionType shouldBe Vda.PICK
        pick.blockingType shouldBe "HARD"
        // The pick left a load on the vehicle.
        eventually(10.seconds) {
            plant.loadHandlingDevices(0) shouldBe listOf(LoadHandlingDevice("LHD-0", full = true))
            length() shouldBe 1500L // vda5050:vehicleLengthLoaded
        }
    }

    test("a drop finishes an order too and empties the vehicle") {
        plant.order("T2", "Goods out 01", "Unload cargo", plant.vehicleName(0))
        eventually(60.seconds) { plant.orderState("T2") shouldBe "FINISHED" }
        val drop = plant.orders.last { it.serialNumber == "SIM-1" }.nodes.last { it.released }.actions.single()
        drop.actionType shouldBe Vda.DROP
        eventually(10.seconds) {
            plant.loadHandlingDevices(0) shouldBe emptyList()
            length() shouldBe 900L
        }
    }

    test("two vehicles contending for a path: every order finishes, nothing is allocated twice") {
        eventually(20.seconds) {
            (0..1).forEach { plant.vehicle(it)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
        }
        // Each vehicle's trip crosses the other's way: after every vehicle event no resource is allocated to both and
        // no point holds both.
        plant.order("A0", "Storage 01", "Load cargo", plant.vehicleName(0))
        plant.order("B0", "Goods out 01", "Unload cargo", plant.vehicleName(1))
        plant.order("A1", "Goods out 01", "Unload cargo", plant.vehicleName(0))
        plant.order("B1", "Storage 02", "Load cargo", plant.vehicleName(1))
        eventually(120.seconds) { listOf("A0", "B0", "A1", "B1").forEach { plant.orderState(it) shouldBe "FINISHED" } }
        violations.shouldBeEmpty()
    }
})
