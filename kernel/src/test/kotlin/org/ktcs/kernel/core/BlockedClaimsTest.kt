package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.scheduling.WaitForGraph
import org.ktcs.kernel.simulation.SimulationKernel

/**
 * A vehicle in a dead-end stub whose new route leaves past the vehicle waiting at the stub's mouth to come in: the
 * warehouse's most frequent deadlock before [BlockedClaims]. The claim waits for itself and has no way around; the
 * vehicle in its way yields at once, before the two have waited long enough to be a deadlock.
 */
class BlockedClaimsTest : FunSpec({
    val config = manualWatchdogConfig()

    // A two-way lane W2 - W1 - M - E with a dead-end stub S at M; E is a dead-end park bay, W2 a junction (on to W3 or
    // N). `In` stands in the stub, `Out` comes from W2 to go into the stub; then `In` is sent to W2, through the
    // point `Out` stands on.
    fun twoWay(from: String, to: String) = Path("$from --- $to", from, to, 1_000, maxReverseVelocity = 1000)
    val plant = PlantModel(
        "stub at a lane",
        points = listOf("W3", "N", "W2", "W1", "M", "S").map { Point(it) } + Point("E", type = PointType.PARK_POSITION),
        paths = listOf(
            twoWay("W3", "W2"),
            twoWay("N", "W2"),
            twoWay("W2", "W1"),
            twoWay("W1", "M"),
            twoWay("M", "S"),
            twoWay("M", "E"),
        ),
        vehicles = listOf(
            Vehicle("In", properties = mapOf("loopback:initialPosition" to "S")),
            Vehicle("Out", properties = mapOf("loopback:initialPosition" to "W2")),
        ),
    )

    fun SimulationKernel.now(action: KernelCore.() -> Unit) = execute(settleMillis = 50, action)

    fun SimulationKernel.order(name: String, vehicle: String, to: String) = now {
        createTransportOrder(TransportOrderCreation(name, listOf(Destination(to, "MOVE")), intendedVehicle = vehicle))
    }

    fun SimulationKernel.check(times: Int) = repeat(times) {
        now { checkForDeadlocks() }
        context.runUntilTime(context.elapsedMillis() + 100)
    }

    test("the vehicle in a blocked claim's way yields through a park bay, and no deadlock is found") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(plant, config, listOf(drivers.module)).use { kernel ->
            kernel.order("ToStub", vehicle = "Out", to = "S")
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 3_000)
            // Out waits at W1: the stub is taken.
            kernel.core.plant.vehicle("Out").currentPosition shouldBe "W1"

            kernel.order("Away", vehicle = "In", to = "W2")
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 100)
            kernel.core.plant.vehicle("In").currentPosition shouldBe "S"

            kernel.check(times = 2)
            kernel.core.watchdog.claimYields shouldBe 1
            kernel.context.runUntil {
                listOf("ToStub", "Away").all { kernel.core.orders.require(it).state.isFinal }
            }
            kernel.core.orders.require("ToStub").state shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("Away").state shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("ToStub").driveOrders.single().route!!.steps.map { it.destinationPoint } shouldBe
                listOf("W1", "M", "E", "M", "S")
            kernel.core.watchdog.detected shouldBe 0
        }
    }

    test("without the yield the same two vehicles are a deadlock the watchdog has to find") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(plant, config, listOf(drivers.module)).use { kernel ->
            kernel.order("ToStub", vehicle = "Out", to = "S")
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 3_000)
            kernel.order("Away", vehicle = "In", to = "W2")
            // Two watchdog periods of waiting make the held-back grant count as a wait; the yield comes before that.
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 2_500)
            WaitForGraph(kernel.core.scheduler.waitsFor()).cycles().map {
                it.toSet()
            } shouldBe listOf(setOf("In", "Out"))
        }
    }
})
