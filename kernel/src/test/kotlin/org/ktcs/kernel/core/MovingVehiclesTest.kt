package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.koin.dsl.module
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.simulation.SimulationKernel

/** A scheduler that grants as the default one does but reports the waits the test sets. */
private class WaitsOfTheTest(inner: Scheduler) : Scheduler by inner {
    var waits: Map<String, Map<String, Set<String>>> = emptyMap()

    override fun waitsFor() = waits
}

/**
 * The deadlock watchdog leaves vehicles that carry out a command out of its cycle search: a cycle of waits through a
 * vehicle under way may end when it arrives, so it is no deadlock yet (on the warehouse most such reports were a
 * vehicle driving into a bay to let another pass). A vehicle whose driver reports nothing for a minute of vehicle time
 * counts as stopped again, so a driver that never reports cannot hide a deadlock.
 */
class MovingVehiclesTest : FunSpec({
    val config = manualWatchdogConfig()
    val plant = PlantModel(
        "lane",
        points = listOf("P1", "P2", "P3", "P4").map { Point(it) },
        paths = listOf(Path("P1 --- P2", "P1", "P2", 1_000), Path("P3 --- P4", "P3", "P4", 1_000)),
        vehicles = listOf(
            Vehicle("A", properties = mapOf("loopback:initialPosition" to "P1")),
            Vehicle("B", properties = mapOf("loopback:initialPosition" to "P3")),
        ),
    )
    val cycle = mapOf("A" to mapOf("B" to setOf("P3")), "B" to mapOf("A" to setOf("P1")))

    // A kernel whose vehicles arrive when the test says so, and whose scheduler reports the waits the test sets.
    fun withHeldDrivers(test: (SimulationKernel, Map<String, HeldDriver>) -> Unit) {
        val drivers = HashMap<String, HeldDriver>()
        val held = heldDrivers(drivers)
        val waits = module { single<Scheduler> { WaitsOfTheTest(DefaultScheduler(get(), get<KernelContext>())) } }
        SimulationKernel(plant, config, listOf(waits, held)).use { kernel -> test(kernel, drivers) }
    }

    // As above, with A sent its step to P2 and not arrived, and the cycle A <-> B reported.
    fun withAUnderWay(test: (SimulationKernel, Map<String, HeldDriver>) -> Unit) = withHeldDrivers { kernel, drivers ->
        kernel.execute(settleMillis = 50) {
            createTransportOrder(TransportOrderCreation("T", listOf(Destination("P2", "MOVE")), intendedVehicle = "A"))
        }
        kernel.core.plant.vehicle("A").allocatedResources.flatten().toSet() shouldBe setOf("P1", "P1 --- P2", "P2")
        (kernel.core.scheduler as WaitsOfTheTest).waits = cycle
        test(kernel, drivers)
    }

    fun SimulationKernel.checks(times: Int) = repeat(times) { execute { checkForDeadlocks() } }

    test("a cycle through a vehicle under way is no deadlock; once it has arrived and still waits, it is") {
        withAUnderWay { kernel, drivers ->
            kernel.checks(5)
            kernel.core.watchdog.detected shouldBe 0

            kernel.execute(settleMillis = 50) { drivers.getValue("A").arrive() }
            kernel.core.plant.vehicle("A").currentPosition shouldBe "P2"
            kernel.checks(1)
            kernel.core.watchdog.detected shouldBe 1
        }
    }

    test("a vehicle whose driver reports nothing for a minute of vehicle time counts as stopped") {
        withAUnderWay { kernel, _ ->
            kernel.checks(60)
            kernel.core.watchdog.detected shouldBe 0
            kernel.checks(1)
            kernel.core.watchdog.detected shouldBe 1
        }
    }

    test("a cycle of vehicles that stand is reported at the first check, as before") {
        withHeldDrivers { kernel, _ ->
            (kernel.core.scheduler as WaitsOfTheTest).waits = cycle
            kernel.checks(1)
            kernel.core.watchdog.detected shouldBe 1
        }
    }
})
