package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.core.RecordingStepDrivers
import org.ktcs.kernel.simulation.SimulationKernel
import org.ktcs.kernel.web.v1.orders.toDto

/** Every DISPATCHABLE order says why it waits (kTCS's waitingReason), and stops saying it once it no longer holds. */
class WaitingReasonTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
    )
    val drivers = RecordingStepDrivers()
    val demo = PlantModelLoader.loadDemo().model
    val trip = listOf(Destination("Goods in north 01", "Load cargo"), Destination("Goods out 02", "Unload cargo"))

    fun SimulationKernel.now(action: KernelCore.() -> Unit) = execute(settleMillis = 50, action)

    fun SimulationKernel.reason(order: String) = core.orders.require(order).toDto().waitingReason

    fun SimulationKernel.order(name: String, vehicle: String? = null) =
        now { createTransportOrder(TransportOrderCreation(name, trip, intendedVehicle = vehicle)) }

    test("no vehicle with a known position: said, and gone once one has a position") {
        val unplaced = demo.copy(vehicles = demo.vehicles.map { it.copy(properties = emptyMap()) })
        SimulationKernel(unplaced, config, listOf(drivers.module)).use { kernel ->
            kernel.order("T")
            kernel.reason("T") shouldBe "no vehicle is available: position unknown"
            kernel.now { drivers.contexts.getValue("Vehicle-01").reportPosition("Point-0001") }
            kernel.reason("T") shouldBe null
        }
    }

    test("a paused intended vehicle: said, and gone once it is resumed") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.now { kernel.core.requests.setPaused("Vehicle-02", true) }
            kernel.order("T", vehicle = "Vehicle-02")
            kernel.reason("T") shouldBe "intended vehicle Vehicle-02: paused"
            kernel.core.plant.vehicle("Vehicle-02").waitingReason shouldBe "paused"
            kernel.now { kernel.core.requests.setPaused("Vehicle-02", false) }
            kernel.reason("T") shouldBe null
            kernel.core.plant.vehicle("Vehicle-02").waitingReason shouldBe null
        }
    }

    test("every vehicle busy: says which vehicles, and gone once one is free") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            listOf("A", "B", "C", "D").forEachIndexed { i, name -> kernel.order(name, vehicle = "Vehicle-0${i + 1}") }
            kernel.order("E")
            kernel.reason("E") shouldBe
                "every vehicle is busy with an order: Vehicle-01, Vehicle-02, Vehicle-03, Vehicle-04"
            kernel.context.runUntil { kernel.core.orders.require("E").state.name != "DISPATCHABLE" }
            kernel.reason("E") shouldBe null
        }
    }

    test("a locked destination: said, and gone once it is unlocked") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.now { kernel.core.requests.setLocationLocked("Goods out 02", true) }
            kernel.order("T")
            kernel.reason("T") shouldBe "target location Goods out 02 is locked"
            kernel.now {
                kernel.core.requests.setLocationLocked("Goods out 02", false)
                kernel.core.dispatch()
            }
            kernel.reason("T") shouldBe null
        }
    }

    test("unfinished dependencies are named while the order is ACTIVE, failed ones too, and gone once finished") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.now { kernel.core.requests.setPaused("Vehicle-02", true) }
            kernel.order("First", vehicle = "Vehicle-01")
            kernel.order("Other", vehicle = "Vehicle-02")
            kernel.now {
                createTransportOrder(TransportOrderCreation("Then", trip, dependencies = setOf("First", "Other")))
            }
            kernel.core.orders.require("Then").state.name shouldBe "ACTIVE"
            kernel.reason("Then") shouldBe "dependencies not finished: First, Other"
            kernel.context.runUntil { kernel.core.orders.require("First").state.isFinal }
            kernel.reason("Then") shouldBe "dependencies not finished: Other"
            kernel.now { kernel.core.requests.setPaused("Vehicle-02", false) }
            kernel.context.runUntil { kernel.core.orders.require("Then").state.name != "ACTIVE" }
            kernel.reason("Then") shouldBe null
        }
    }

    test("a failed dependency is named: the order can never be dispatched") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.order("First", vehicle = "Vehicle-01")
            kernel.now {
                createTransportOrder(TransportOrderCreation("Then", trip, dependencies = setOf("First")))
                withdraw("First", true, false)
            }
            kernel.reason("Then") shouldBe
                "dependencies failed, so it never becomes dispatchable (withdraw it): First"
        }
    }

    test("no route: the locked path in the way is named, and the reason is gone once it is unlocked") {
        val line = PlantModel(
            "line",
            points = listOf("A", "B", "C").map { Point(it) },
            paths = listOf(Path("A --- B", "A", "B", 1_000), Path("B --- C", "B", "C", 1_000, locked = true)),
            vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
        )
        SimulationKernel(line, config, listOf(drivers.module)).use { kernel ->
            kernel.now { createTransportOrder(TransportOrderCreation("T", listOf(Destination("C", "MOVE")))) }
            kernel.reason("T") shouldBe "vehicle V: no route from A (locked path B --- C blocks the way)"
            kernel.now {
                setPathLocked("B --- C", false)
                dispatch()
            }
            kernel.reason("T") shouldBe null
        }
    }

    test("each change of reason is one history entry") {
        SimulationKernel(demo, config, listOf(drivers.module)).use { kernel ->
            kernel.now { kernel.core.requests.setPaused("Vehicle-02", true) }
            kernel.order("T", vehicle = "Vehicle-02")
            kernel.now { kernel.core.dispatch() }
            kernel.now { kernel.core.requests.setLocationLocked("Goods out 02", true) }
            kernel.now { kernel.core.dispatch() }
            kernel.core.orders.require("T").history.filter { it.eventCode == "tcs:history:orderDispatchingDeferred" }
                .map { it.supplement } shouldBe
                listOf("intended vehicle Vehicle-02: paused", "target location Goods out 02 is locked")
        }
    }
})
