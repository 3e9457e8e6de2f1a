package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.scheduling.SchedulerClient
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.simulation.SimulationKernel

/** Rerouting on request, as openTCS's operators know it: regular from where the route goes on, forced from where the vehicle stands. */
class RerouteTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
    )
    // A -> W -> X -> B -> D is the way; Y, off it, has a path of its own to D and one from X.
    val model = PlantModel(
        "reroute",
        points = listOf("A", "W", "X", "B", "D", "Y").map { Point(it) },
        paths = listOf(
            Path("A --- W", "A", "W", 10_000),
            Path("W --- X", "W", "X", 10_000),
            Path("X --- B", "X", "B", 1_000),
            Path("B --- D", "B", "D", 1_000),
            Path("Y --- D", "Y", "D", 2_000),
            Path("X --- Y", "X", "Y", 2_000),
        ),
        vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
    )

    fun SimulationKernel.now(action: KernelCore.() -> Unit) = execute(settleMillis = 50, action)

    fun SimulationKernel.reroute(forced: Boolean): String? {
        var refusal: String? = null
        now {
            refusal = runCatching { requests.reroute("V", forced) }.exceptionOrNull()?.message
                ?.removePrefix("cannot reroute vehicle 'V': ")
        }
        return refusal
    }

    /** V gets the order to D, is paused once under way and stands at X, then is carried by hand to Y. */
    fun SimulationKernel.carriedOffItsRoute(drivers: RecordingStepDrivers) {
        now { createTransportOrder(TransportOrderCreation("T", listOf(Destination("D", "MOVE")))) }
        context.runUntilTime(context.elapsedMillis() + 1_000)
        now { requests.setPaused("V", true) }
        context.runUntilTime(context.elapsedMillis() + 30_000)
        core.plant.vehicle("V").currentPosition shouldBe "X"
        now { drivers.contexts.getValue("V").reportPosition("Y") }
    }

    test("a vehicle without an order is not rerouted, and says why") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module)).use { kernel ->
            kernel.reroute(forced = false) shouldBe "vehicle V has no transport order"
            kernel.reroute(forced = true) shouldBe "vehicle V has no transport order"
        }
    }

    test("regular rerouting refuses a vehicle off its route; forced rerouting starts where it stands") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module)).use { kernel ->
            kernel.carriedOffItsRoute(drivers)
            kernel.reroute(forced = false)!! shouldContain "stands at Y, not at X"
            kernel.reroute(forced = true) shouldBe null
            kernel.core.plant.vehicle("V").allocatedResources shouldBe listOf(setOf("Y"))
            kernel.now { requests.setPaused("V", false) }
            kernel.context.runUntil { kernel.core.orders.require("T").state.isFinal }
            kernel.core.orders.require("T").state shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("T").driveOrders.single().route!!.steps.map { it.path } shouldBe
                listOf("A --- W", "W --- X", "Y --- D")
        }
    }

    test("without a route the vehicle keeps its route, and the refusal names the locked path in the way") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module)).use { kernel ->
            kernel.now { setPathLocked("Y --- D", true) }
            kernel.carriedOffItsRoute(drivers)
            kernel.reroute(forced = true) shouldBe
                "no route for vehicle V from Y to D: locked path Y --- D blocks the way"
            kernel.core.orders.require("T").driveOrders.single().route!!.steps.map { it.path } shouldBe
                listOf("A --- W", "W --- X", "X --- B", "B --- D")
            kernel.now { setPathLocked("Y --- D", false) }
            kernel.reroute(forced = true) shouldBe null
        }
    }

    test("a vehicle already sent to its destination has nothing to reroute: not counted as rerouted, not refused") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module)).use { kernel ->
            kernel.now { createTransportOrder(TransportOrderCreation("T", listOf(Destination("W", "MOVE")))) }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)
            var rerouted: Boolean? = null
            kernel.now { rerouted = reroute("V", avoid = emptySet()) }
            // The deadlock watchdog relies on this: a vehicle that did not change its way did not resolve anything.
            rerouted shouldBe false
            kernel.reroute(forced = false) shouldBe null
        }
    }

    test("a deadlock past the current drive order is broken by routing the later drive orders around it") {
        // The order goes to W, then on to D; the watchdog finds what to avoid (B) on the second drive order only.
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module)).use { kernel ->
            kernel.now {
                createTransportOrder(
                    TransportOrderCreation("T", listOf(Destination("X", "MOVE"), Destination("D", "MOVE"))),
                )
            }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)
            var rerouted: Boolean? = null
            kernel.now { rerouted = reroute("V", avoid = setOf("B")) }

            rerouted shouldBe true
            kernel.context.runUntil { kernel.core.orders.require("T").state.isFinal }
            kernel.core.orders.require("T").state shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("T").driveOrders.last().route!!.steps.map { it.path } shouldBe
                listOf("X --- Y", "Y --- D")
        }
    }

    test("the watchdog's reroute is not taken when the new route would close another cycle of waiting vehicles") {
        // V at A waits for X (held by bx). The way around X, over Y, leads into b1 at Y, who waits for Z (b2), who
        // waits for A, where V stands: taking it would trade one deadlock for another, and back at the next check.
        val loop = PlantModel(
            "reroute-into-a-loop",
            points = listOf("A", "X", "Y", "Z", "D").map { Point(it) },
            paths = listOf(
                Path("A --- X", "A", "X", 1_000),
                Path("X --- D", "X", "D", 1_000),
                Path("A --- Y", "A", "Y", 2_000),
                Path("Y --- D", "Y", "D", 2_000),
                Path("Y --- Z", "Y", "Z", 1_000),
                Path("Z --- A", "Z", "A", 1_000),
            ),
            vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
        )
        val drivers = RecordingStepDrivers()
        SimulationKernel(loop, config, listOf(drivers.module)).use { kernel ->
            val (bx, b1, b2) = listOf("bx", "b1", "b2").map { blockerName ->
                object : SchedulerClient {
                    override val name = blockerName

                    override fun onAllocationGranted(resources: Set<String>) = true
                }
            }
            kernel.now {
                scheduler.allocateNow(bx, setOf("X"))
                scheduler.allocateNow(b1, setOf("Y"))
                scheduler.allocateNow(b2, setOf("Z"))
                scheduler.claim(b1, listOf(setOf("Y --- Z", "Z")))
                scheduler.claim(b2, listOf(setOf("Z --- A", "A")))
                createTransportOrder(TransportOrderCreation("T", listOf(Destination("D", "MOVE"))))
            }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)
            kernel.now { scheduler.pendingAllocations()["V"] shouldBe listOf(setOf("A --- X", "X")) }

            var rerouted: Boolean? = null
            kernel.now { rerouted = reroute("V", avoid = setOf("A --- X", "X")) }

            rerouted shouldBe false
            kernel.core.orders.require("T").driveOrders.single().route!!.steps.map { it.path } shouldBe
                listOf("A --- X", "X --- D")
            kernel.now { scheduler.free(bx, setOf("X")) }
            kernel.context.runUntil { kernel.core.orders.require("T").state.isFinal }
            kernel.core.orders.require("T").state shouldBe TransportOrderState.FINISHED
        }
    }

    test("routing the later drive orders anew while the vehicle waits for a grant keeps that step in its claim") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module)).use { kernel ->
            val blocker = object : SchedulerClient {
                override val name = "blocker"

                override fun onAllocationGranted(resources: Set<String>) = true
            }
            kernel.now {
                scheduler.allocateNow(blocker, setOf("W"))
                createTransportOrder(
                    TransportOrderCreation("T", listOf(Destination("X", "MOVE"), Destination("D", "MOVE"))),
                )
            }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)
            kernel.now { scheduler.pendingAllocations()["V"] shouldBe listOf(setOf("A --- W", "W")) }

            var rerouted: Boolean? = null
            kernel.now { rerouted = reroute("V", avoid = setOf("B")) }

            rerouted shouldBe true
            kernel.now {
                (scheduler as DefaultScheduler).claims().getValue("V").first() shouldBe setOf("A --- W", "W")
            }
        }
    }
})
