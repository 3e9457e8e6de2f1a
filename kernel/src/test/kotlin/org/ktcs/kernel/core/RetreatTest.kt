package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.koin.dsl.module
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.scheduling.Retreat
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.simulation.SimulationKernel

/** A scheduler in place of the default one (no [DefaultScheduler]) that offers the retreats a test sets. */
private class RetreatingScheduler(inner: Scheduler) : Scheduler by inner {
    var offered: List<Retreat> = emptyList()
    var asked = 0
    var bay: String? = null

    override fun retreatPoint(client: String): String? = bay

    override fun retreats(eligible: (String) -> Boolean): Sequence<Retreat> {
        asked++
        return offered.asSequence().filter { eligible(it.vehicle) }
    }
}

/**
 * Retreats as the deadlock watchdog sends them: it asks the scheduler in place through the `api` interface, and a
 * vehicle sent is routed on through the park point to where it was going.
 */
class RetreatTest : FunSpec({
    val config = manualWatchdogConfig()
    // A -> W -> X -> B -> D is the way; the park point P is a detour from X back to B.
    val model = PlantModel(
        "retreat",
        points = listOf("A", "W", "X", "B", "D").map { Point(it) } + Point("P", type = PointType.PARK_POSITION),
        paths = listOf(
            Path("A --- W", "A", "W", 10_000),
            Path("W --- X", "W", "X", 10_000),
            Path("X --- B", "X", "B", 1_000),
            Path("B --- D", "B", "D", 1_000),
            Path("X --- P", "X", "P", 2_000),
            Path("P --- B", "P", "B", 2_000),
        ),
        vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
    )
    val replacing = module {
        single<Scheduler> { RetreatingScheduler(DefaultScheduler(get(), get<KernelContext>())) }
    }

    fun SimulationKernel.now(action: KernelCore.() -> Unit) = execute(settleMillis = 50, action)

    test("a retreat the replaced scheduler offers is sent, and the vehicle goes on through the park point") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module, replacing)).use { kernel ->
            val scheduler = kernel.core.scheduler as RetreatingScheduler
            kernel.now { createTransportOrder(TransportOrderCreation("T", listOf(Destination("D", "MOVE")))) }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 1_000)

            kernel.now { checkForDeadlocks() }
            scheduler.asked shouldBe 1
            kernel.core.watchdog.retreats shouldBe 0

            scheduler.offered = listOf(Retreat("V", "P"))
            kernel.now { checkForDeadlocks() }
            kernel.core.watchdog.retreats shouldBe 1
            // Sent once, then left alone for a while: a retreat that did not help must not keep the vehicle circling.
            kernel.now { checkForDeadlocks() }
            kernel.core.watchdog.retreats shouldBe 1

            kernel.context.runUntil { kernel.core.orders.require("T").state.isFinal }
            val order = kernel.core.orders.require("T")
            order.state shouldBe TransportOrderState.FINISHED
            order.driveOrders.single().route!!.steps.map { it.path } shouldBe
                listOf("A --- W", "W --- X", "X --- P", "P --- B", "B --- D")
        }
    }

    test("a vehicle sent through a bay to break a deadlock is not sent through the same bay again at once") {
        // V at A is bound for D past U, which stands on B; its only way aside is the park point P.
        val blocked = PlantModel(
            "bay",
            points = listOf("A", "B", "D").map { Point(it) } + Point("P", type = PointType.PARK_POSITION),
            paths = listOf(
                Path("A --- B", "A", "B", 1_000),
                Path("B --- D", "B", "D", 1_000),
                Path("A --- P", "A", "P", 1_000),
                Path("P --- B", "P", "B", 1_000),
            ),
            vehicles = listOf(
                Vehicle("V", properties = mapOf("loopback:initialPosition" to "A")),
                Vehicle("U", properties = mapOf("loopback:initialPosition" to "B")),
            ),
        )
        val drivers = RecordingStepDrivers()
        SimulationKernel(blocked, config, listOf(drivers.module, replacing)).use { kernel ->
            (kernel.core.scheduler as RetreatingScheduler).bay = "P"
            kernel.now {
                createTransportOrder(
                    TransportOrderCreation("T", listOf(Destination("D", "MOVE")), intendedVehicle = "V"),
                )
            }
            var sent = emptyList<Boolean>()
            kernel.now {
                val retreats = Retreats(this)
                sent = listOf(retreats.breakCycle(listOf("V")), retreats.breakCycle(listOf("V")))
            }

            sent shouldBe listOf(true, false)
            kernel.core.orders.require("T").driveOrders.single().route!!.steps.map { it.destinationPoint } shouldBe
                listOf("P", "B", "D")
        }
    }

    test("a vehicle sent the last step of its drive order is not sent through a bay: it arrives and goes on") {
        // V at A goes to D, then back to A; the park point P lies beside B, on its way.
        val bayOnTheWay = PlantModel(
            "last step",
            points = listOf("A", "B", "D").map { Point(it) } + Point("P", type = PointType.PARK_POSITION),
            paths = listOf(
                Path("A --- B", "A", "B", 1_000, maxReverseVelocity = 1_000),
                Path("B --- D", "B", "D", 1_000, maxReverseVelocity = 1_000),
                Path("B --- P", "B", "P", 1_000, maxReverseVelocity = 1_000),
            ),
            vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
        )
        val drivers = HashMap<String, HeldDriver>()
        SimulationKernel(bayOnTheWay, config, listOf(heldDrivers(drivers))).use { kernel ->
            kernel.now {
                createTransportOrder(
                    TransportOrderCreation("T", listOf(Destination("D", "MOVE"), Destination("A", "MOVE"))),
                )
            }
            val driver = drivers.getValue("V")
            driver.sentCommands.map { it.step.destinationPoint } shouldBe listOf("B", "D")

            var retreated = true
            kernel.now { retreated = retreat("V", "P", emptySet()) }
            retreated shouldBe false

            // Once sent, a detour after the last step would be driven as steps of the next drive order.
            while (!kernel.core.orders.require("T").state.isFinal) {
                kernel.now { driver.arrive() }
            }
            val order = kernel.core.orders.require("T")
            order.state shouldBe TransportOrderState.FINISHED
            order.driveOrders.map { leg -> leg.route!!.steps.map { it.destinationPoint } } shouldBe
                listOf(listOf("B", "D"), listOf("B", "A"))
            kernel.core.plant.vehicle("V").currentPosition shouldBe "A"
        }
    }

    test("a vehicle sent through a bay asks for the way back out only once in it, so the point it left is freed") {
        // V at X and U at D are both bound for A, where W stands; the bay P beside X lets U pass V (B and E are other
        // ways on, so that nobody waits for a vehicle standing at a dead end).
        val lane = PlantModel(
            "lane with a bay",
            points = listOf("A", "B", "X", "D", "E").map { Point(it) } + Point("P", type = PointType.PARK_POSITION),
            paths = listOf("B" to "A", "A" to "X", "X" to "D", "X" to "E", "X" to "P").map { (from, to) ->
                Path("$from --- $to", from, to, 1_000, maxReverseVelocity = 1_000)
            },
            vehicles = listOf("V" to "X", "U" to "D", "W" to "A").map { (name, at) ->
                Vehicle(name, properties = mapOf("loopback:initialPosition" to at))
            },
        )
        val drivers = HashMap<String, HeldDriver>()
        SimulationKernel(lane, config, listOf(heldDrivers(drivers))).use { kernel ->
            kernel.now {
                for (vehicle in listOf("V", "U")) {
                    createTransportOrder(
                        TransportOrderCreation(
                            "$vehicle-A",
                            listOf(Destination("A", "MOVE")),
                            intendedVehicle = vehicle,
                        ),
                    )
                }
            }
            var retreated = false
            kernel.now { retreated = retreat("V", "P", emptySet()) }
            retreated shouldBe true
            drivers.getValue("V").sentCommands.map { it.step.destinationPoint } shouldBe listOf("P")

            kernel.now { drivers.getValue("V").arrive() }
            // Asked for at once, the way back would have kept X held all along, and U would still wait for it.
            drivers.getValue("U").sentCommands.map { it.step.destinationPoint } shouldBe listOf("X")
            drivers.getValue("V").sentCommands shouldBe emptyList()
        }
    }

    test("a vehicle without a transport order is not sent, and the watchdog goes on to look for deadlocks") {
        val drivers = RecordingStepDrivers()
        SimulationKernel(model, config, listOf(drivers.module, replacing)).use { kernel ->
            val scheduler = kernel.core.scheduler as RetreatingScheduler
            scheduler.offered = listOf(Retreat("V", "P"))
            kernel.now { checkForDeadlocks() }
            scheduler.asked shouldBe 1
            kernel.core.watchdog.retreats shouldBe 0
            kernel.core.plant.vehicle("V").currentPosition shouldBe "A"
        }
    }
})
