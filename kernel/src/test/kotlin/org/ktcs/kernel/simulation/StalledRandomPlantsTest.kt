package org.ktcs.kernel.simulation

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.Lane.BACKWARD
import org.ktcs.kernel.simulation.Lane.FORWARD
import org.ktcs.kernel.simulation.Lane.NONE
import org.ktcs.kernel.simulation.Lane.TWO_WAY

/** Random plants on which the fleet once stopped for good (found by scanning `TrafficPropertyTest`'s generator). */
class StalledRandomPlantsTest : FunSpec({
    // A 3x3 one-way grid with a single-vehicle block: a vehicle on the block's way out waited for the block's holder,
    // who waited for it. The watchdog sent it into the free park bay beyond the next point, but the step to the bay's
    // mouth was judged as if it stood there for good and was refused: 4 of 8 orders finished.
    test("a vehicle sent into a park bay is granted the bay's mouth, judged as it will stand in the bay") {
        val lanes = listOf(
            BACKWARD, FORWARD, BACKWARD, BACKWARD, FORWARD, BACKWARD,
            FORWARD, FORWARD, BACKWARD, BACKWARD, FORWARD, FORWARD,
        )
        runs(RandomPlant(3, 3, lanes, 4, 4, true, -3502435087536113702L), 8981339568532049663L)
    }

    // A 3x4 two-way grid with both kinds of block: a vehicle sent to park in a bay met, at the bay's mouth, a vehicle
    // the watchdog had sent into the same bay to let others pass; neither could move: 6 of 8 orders finished.
    test("a vehicle is sent into no bay where another vehicle's order ends") {
        val lanes = listOf(
            TWO_WAY, TWO_WAY, NONE, TWO_WAY, TWO_WAY, TWO_WAY, TWO_WAY, NONE, TWO_WAY,
            TWO_WAY, TWO_WAY, NONE, TWO_WAY, TWO_WAY, NONE, TWO_WAY, TWO_WAY,
        )
        runs(RandomPlant(3, 4, lanes, 3, 4, true, -2607860026918067736L), -4386970760727166545L)
    }

    // A 3x3 one-way grid with a single-vehicle block between two station stubs: each vehicle stood in one stub bound
    // for the other's, so the local rule held both entries to the block back, for good; the watchdog reported the
    // pair after two periods. Now one of them retreats at the first check.
    test("two vehicles that the local rule holds back for each other: one retreats before it counts as a deadlock") {
        val lanes = listOf(
            FORWARD, BACKWARD, BACKWARD, BACKWARD, FORWARD, FORWARD,
            BACKWARD, FORWARD, FORWARD, BACKWARD, BACKWARD, BACKWARD,
        )
        val report = runs(RandomPlant(3, 3, lanes, 3, 2, true, 1415255446207580030L), 536509924367207191L)
        report.deadlocksDetected shouldBe 0
    }

    // A 3x3 two-way grid with a corridor of two points and a station stub beside each: the vehicle in one stub, bound
    // for the other (taken), held the corridor's direction for its way out (its gate), and the vehicle in the other
    // stub had to leave the other way: 1 of 8 orders finished. Now a gate held back for the report delay opens.
    test("a vehicle held back in a station stub gives up its corridor gate") {
        val lanes =
            listOf(NONE, TWO_WAY, TWO_WAY, TWO_WAY, NONE, TWO_WAY, TWO_WAY, TWO_WAY, TWO_WAY, TWO_WAY, TWO_WAY, TWO_WAY)
        runs(RandomPlant(3, 3, lanes, 3, 4, true, 1309181810394208711L), 1434328759971181348L)
    }

    // A 3x3 grid of one-way and two-way lanes with a single-vehicle block: a vehicle of a blocked claim stepped aside
    // onto a point of the block, holding the whole block in the way of the vehicle that had to cross it next: 1 of 8
    // orders finished. Now side steps do not stop in such a block.
    test("a side step does not stop on a point of a single-vehicle block") {
        val lanes = listOf(
            NONE, TWO_WAY, BACKWARD, NONE, FORWARD, BACKWARD,
            TWO_WAY, FORWARD, BACKWARD, BACKWARD, FORWARD, FORWARD,
        )
        runs(RandomPlant(3, 3, lanes, 4, 4, true, -485365344899405251L), 7112968208872129199L)
    }
}) {
    private companion object {
        const val ORDERS = 8

        fun runs(plant: RandomPlant, orderSeed: Long): SimulationReport {
            val config = ConfigLoader().load(null, emptyMap(), emptyList())
            val report = SimulationRunner(plant.build(), config, listOf(stepVehicles), ORDERS, orderSeed).run()
            withClue(report.lines().joinToString("\n")) {
                report.ordersFinished shouldBe ORDERS
                report.doubleAllocations shouldBe 0
                report.sharedPositions shouldBe 0
            }
            return report
        }
    }
}
