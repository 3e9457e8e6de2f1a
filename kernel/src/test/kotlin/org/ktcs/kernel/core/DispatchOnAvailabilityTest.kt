package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.koin.dsl.module
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.extension.KernelDefaults
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.dispatching.DefaultDispatcher
import org.ktcs.kernel.dispatching.IncrementalDispatcher
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

    test("a vehicle busy with an order it may not leave runs no dispatcher when it reports state or energy") {
        var runs = 0
        val counted = countingDispatcher { runs++ }
        SimulationKernel(demo, config, listOf(drivers.module, counted)).use { kernel ->
            kernel.now { createTransportOrder(TransportOrderCreation("T", trip, intendedVehicle = "Vehicle-01")) }
            kernel.state("T") shouldBe TransportOrderState.BEING_PROCESSED
            val busy = drivers.contexts.getValue("Vehicle-01")
            val idle = drivers.contexts.getValue("Vehicle-02")

            val before = runs
            kernel.now {
                busy.reportEnergyLevel(37)
                busy.reportState(VehicleState.UNAVAILABLE)
            }
            runs shouldBe before
            kernel.now { busy.reportState(VehicleState.CHARGING) }
            runs shouldBeGreaterThan before

            val charging = runs
            kernel.now { idle.reportEnergyLevel(41) }
            runs shouldBeGreaterThan charging
        }
    }

    test("an order given to a vehicle asks for no full run: its routes change as it leaves the waiting orders") {
        var fullRuns = 0
        var runsOnChanges = 0
        val counted = countingDispatcher { full -> if (full) fullRuns++ else runsOnChanges++ }
        SimulationKernel(demo, config, listOf(drivers.module, counted)).use { kernel ->
            kernel.now { }
            val fullBefore = fullRuns
            kernel.now { createTransportOrder(TransportOrderCreation("T", trip, intendedVehicle = "Vehicle-01")) }
            kernel.state("T") shouldBe TransportOrderState.BEING_PROCESSED
            kernel.now { }

            runsOnChanges shouldBeGreaterThan 0
            fullRuns shouldBe fullBefore
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

/** A module that gives the kernel its default dispatcher, telling [ran] of each run (`true`: a full run). */
private fun countingDispatcher(ran: (Boolean) -> Unit) = module {
    single<KernelDefaults> {
        val scope = this
        object : KernelDefaults {
            override fun dispatcher(): Dispatcher =
                CountingDispatcher(DefaultDispatcher(scope.get(), scope.get(), scope.get()), ran)
        }
    }
}

/** The kernel's dispatcher, counting its runs (full runs with `true`). */
private class CountingDispatcher(private val dispatcher: DefaultDispatcher, private val ran: (Boolean) -> Unit) :
    IncrementalDispatcher {
    override fun initialize() = dispatcher.initialize()

    override fun terminate() = dispatcher.terminate()

    override fun dispatch() {
        ran(true)
        dispatcher.dispatch()
    }

    override fun dispatchChanges(newOrders: Collection<String>) {
        ran(false)
        dispatcher.dispatchChanges(newOrders)
    }
}
