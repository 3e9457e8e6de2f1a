package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel

/** The dispatcher runs the moment a vehicle becomes able to work, not at its next periodic run (10 s). */
class DispatchOnAvailabilityTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
    )
    val drivers = RecordingStepDrivers()
    val demo = PlantModelLoader.loadDemo().model
    val unplaced = demo.copy(
        vehicles = demo.vehicles.map { it.copy(properties = it.properties - "loopback:initialPosition") },
    )
    val trip = listOf(Destination("Goods in north 01", "Load cargo"))

    fun SimulationKernel.state(order: String) = core.orders.require(order).state

    fun SimulationKernel.now(action: KernelCore.() -> Unit) = execute(settleMillis = 50, action)

    test("a vehicle that gets a position takes the waiting order at once") {
        SimulationKernel(unplaced, config, listOf(drivers.module)).use { kernel ->
            kernel.now {
                kernel.core.createTransportOrder(TransportOrderCreation("T", trip, intendedVehicle = "Vehicle-01"))
            }
            kernel.state("T") shouldBe TransportOrderState.DISPATCHABLE
            kernel.now { drivers.contexts.getValue("Vehicle-01").reportPosition("Point-0001") }
            kernel.state("T") shouldBe TransportOrderState.BEING_PROCESSED
        }
    }

    test("a dispensable order replaced by real work says so in its history") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            val far = listOf(Destination("Goods out 02", "NOP"))
            kernel.now {
                createTransportOrder(
                    TransportOrderCreation("Park", far, intendedVehicle = "Vehicle-01", dispensable = true),
                )
            }
            kernel.now { createTransportOrder(TransportOrderCreation("Work", trip, intendedVehicle = "Vehicle-01")) }
            kernel.context.runUntil { kernel.core.orders.require("Park").state.isFinal }
            kernel.core.orders.require("Park").history.last().supplement shouldBe "replaced by order Work"
        }
    }
})
