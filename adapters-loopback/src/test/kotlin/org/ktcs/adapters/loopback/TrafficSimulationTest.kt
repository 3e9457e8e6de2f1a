package org.ktcs.adapters.loopback

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationReport
import org.ktcs.kernel.simulation.SimulationRunner
import org.ktcs.kernel.simulation.TrafficGrid
import org.ktcs.kernel.simulation.WarehousePlant

/** The traffic benchmark plant with loopback vehicles: deadlock avoidance keeps every fleet moving. */
class TrafficSimulationTest : FunSpec({
    val config = ConfigLoader().load(null, emptyMap(), listOf("loopback.timeFactor=100"))

    fun run(width: Int, height: Int, vehicles: Int, orders: Int, seed: Long, realTime: Boolean): SimulationReport =
        SimulationRunner(
            TrafficGrid(width, height, vehicles).build(),
            config,
            listOf(LoopbackExtension()),
            orders,
            seed,
            realTime = realTime,
        ).run()

    fun SimulationReport.shouldBeClean(orders: Int) {
        listOf(ordersFinished, deadlocksDetected, doubleAllocations, sharedPositions) shouldBe listOf(orders, 0, 0, 0)
    }

    test("virtual time and the wall clock (time factor 100) give the same outcome on a small grid") {
        val virtual = run(6, 6, 5, 40, seed = 3, realTime = false)
        val real = run(6, 6, 5, 40, seed = 3, realTime = true)
        virtual.shouldBeClean(40)
        real.shouldBeClean(40)
        real.clock shouldBe "real time, time factor 100.0"
    }

    // Main at the start of round 14 finished 5 of the 40 at time factor 100: the watchdog's period and the scheduler's
    // patience ran on the kernel clock, so its vehicles drove 100 s between checks and a retreat's cool-down of 60
    // checks outlasted the stall limit.
    test("a small warehouse finishes every order at time factor 100 as at 1: traffic timers run in vehicle time") {
        fun warehouse(timeFactor: Double) = SimulationRunner(
            WarehousePlant(3, 6, 4).build(),
            ConfigLoader().load(null, emptyMap(), listOf("loopback.timeFactor=$timeFactor")),
            listOf(LoopbackExtension()),
            40,
            1,
        ).run()
        for (report in listOf(warehouse(1.0), warehouse(100.0))) {
            withClue(report.lines().joinToString("\n")) {
                listOf(
                    report.ordersFinished,
                    report.doubleAllocations,
                    report.sharedPositions,
                ) shouldBe listOf(40, 0, 0)
            }
        }
    }

    test("random one-way grids, fleets and order batches: every order finishes, no deadlock, no shared resource") {
        checkAll(
            PropTestConfig(seed = 11, iterations = 12),
            Arb.int(4..9),
            Arb.int(4..9),
            Arb.int(1..12),
            Arb.long(0L..1_000L),
        ) { width, height, wanted, seed ->
            val vehicles = wanted.coerceAtMost(2 * (width + height) - 4)
            run(width, height, vehicles, 60, seed, realTime = false).shouldBeClean(60)
        }
    }
})
