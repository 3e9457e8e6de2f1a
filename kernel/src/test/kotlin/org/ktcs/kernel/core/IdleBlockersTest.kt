package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel

/**
 * A lane A -> B -> C with a siding B <-> D. Vehicle "Parked" stands idle on the park position B, on the lane;
 * vehicle "Worker" at A is sent to C and must pass B.
 */
class IdleBlockersTest : FunSpec({
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
    val plant = PlantModel(
        "siding",
        points = listOf(
            Point("A"),
            Point("B", type = PointType.PARK_POSITION),
            Point("C"),
            Point("D", type = PointType.PARK_POSITION),
        ),
        paths = listOf(
            Path("A --- B", "A", "B", length = 1000),
            Path("B --- C", "B", "C", length = 1000),
            Path("B --- D", "B", "D", length = 1000),
            Path("D --- B", "D", "B", length = 1000),
        ),
        vehicles = listOf(
            Vehicle("Worker", properties = mapOf("loopback:initialPosition" to "A")),
            Vehicle("Parked", properties = mapOf("loopback:initialPosition" to "B")),
        ),
    )

    fun kernel(vararg settings: String): SimulationKernel {
        val defaults = listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false")
        val config = ConfigLoader().load(null, emptyMap(), defaults + settings)
        return SimulationKernel(plant, config, listOf(drivers))
    }

    fun SimulationKernel.sendWorkerToC() {
        val order = TransportOrderCreation(
            "T1",
            listOf(Destination("C", Operations.MOVE)),
            intendedVehicle = "Worker",
        )
        context.execute { core.createTransportOrder(order) }
        val tenMinutes = 600_000L
        context.runUntil { core.orders.get("T1")?.state?.isFinal == true || context.elapsedMillis() > tenMinutes }
    }

    test("an idle vehicle in the way of a waiting one is sent to a free park position off its route") {
        kernel().use { kernel ->
            kernel.sendWorkerToC()

            kernel.core.orders.require("T1").state shouldBe TransportOrderState.FINISHED
            kernel.core.plant.vehicle("Parked").currentPosition shouldBe "D"
            kernel.core.watchdog.idleVehiclesMoved shouldBe 1
            val cleared = kernel.core.orders.all().single { it.name.startsWith("Clear-") }
            cleared.processingVehicle shouldBe "Parked"
            cleared.state shouldBe TransportOrderState.FINISHED
        }
    }

    // The watchdog once checked only the allowed types: it sent a Clear- order the dispatcher never assigned.
    test("an idle vehicle that does not accept park orders is not sent an order it would never take") {
        kernel().use { kernel ->
            kernel.context.execute {
                kernel.core.requests.updateVehicle("Parked") {
                    it.copy(acceptableOrderTypes = setOf(AcceptableOrderType("Transport", 0)))
                }
            }
            kernel.sendWorkerToC()

            kernel.core.watchdog.idleVehiclesMoved shouldBe 0
            kernel.core.orders.all().filter { it.name.startsWith("Clear-") } shouldBe emptyList()
        }
    }

    test("without the watchdog the worker waits behind the idle vehicle for good") {
        kernel("kernel.deadlockCheckInterval=0").use { kernel ->
            kernel.sendWorkerToC()

            kernel.core.orders.require("T1").state shouldBe TransportOrderState.BEING_PROCESSED
            kernel.core.plant.vehicle("Worker").currentPosition shouldBe "A"
        }
    }
})
