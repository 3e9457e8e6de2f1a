package org.ktcs.kernel.simulation

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.filter
import io.kotest.property.arbitrary.flatMap
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.checkAll
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriverFactory

internal val stepVehicles = object : KtcsExtension {
    override val name = "step vehicles"

    override fun module() = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
}

private fun lanes(weights: List<Pair<Int, Lane>>) = Arb.element(
    weights.flatMap { (weight, lane) ->
        List(weight) { lane }
    },
)

/** Random strongly connected plants of [laneKinds]: 3x3 to 4x4 grids with stations and park bays on dead-end stubs, maybe blocks. */
internal fun trafficPlants(laneKinds: List<Pair<Int, Lane>>): Arb<RandomPlant> =
    Arb.int(3..4).flatMap { width ->
        Arb.int(3..4).flatMap { height ->
            Arb.list(lanes(laneKinds), RandomPlant.laneCount(width, height)..RandomPlant.laneCount(width, height))
                .flatMap { lanes ->
                    Arb.int(3..4).flatMap { stations ->
                        Arb.int(2..4).flatMap { vehicles ->
                            Arb.boolean().flatMap { blocks ->
                                Arb.long().map { seed ->
                                    RandomPlant(width, height, lanes, stations, vehicles, blocks, seed)
                                }
                            }
                        }
                    }
                }
        }
    }.filter(RandomPlant::isStronglyConnected)

internal val oneWay = listOf(3 to Lane.FORWARD, 3 to Lane.BACKWARD, 1 to Lane.NONE)
internal val mixed = listOf(3 to Lane.FORWARD, 3 to Lane.BACKWARD, 2 to Lane.TWO_WAY, 1 to Lane.NONE)
internal val twoWay = listOf(6 to Lane.TWO_WAY, 1 to Lane.NONE)

/**
 * Runs [iterations] random plants of [lanes], each with a random stream of orders, in virtual time as `ktcs simulate`
 * does, and checks each run's report.
 */
private suspend fun forRandomRuns(
    lanes: List<Pair<Int, Lane>>,
    seed: Long,
    iterations: Int,
    check: SimulationReport.(orders: Int) -> Unit,
) {
    checkAll(PropTestConfig(seed = seed, iterations = iterations), trafficPlants(lanes), Arb.int(4..10), Arb.long()) {
            plant,
            orders,
            orderSeed,
        ->
        val config = ConfigLoader().load(null, emptyMap(), emptyList())
        val report = SimulationRunner(plant.build(), config, listOf(stepVehicles), orders, orderSeed).run()
        withClue("$plant, $orders orders, seed $orderSeed:\n${report.lines().joinToString("\n")}") {
            report.check(orders)
        }
    }
}

/**
 * Random small plants and order streams in virtual time (the kernel's code and timing, test vehicles at 1 m/s). Each
 * run simulates until every order is final or an hour passes without progress.
 */
class TrafficPropertyTest : FunSpec({
    context("nothing is held twice, and the fleet never stops without the watchdog reporting why") {
        val kinds = listOf("one-way lanes" to oneWay, "one-way and two-way lanes" to mixed)
        withData(nameFn = { it.first }, kinds) { (_, lanes) ->
            forRandomRuns(lanes, seed = 1_111, iterations = 25) { orders ->
                doubleAllocations shouldBe 0
                sharedPositions shouldBe 0
                val done = ordersFinished + ordersUnroutable == orders
                (done || deadlocksDetected > 0) shouldBe true
            }
        }
    }

    // Half of issue #11's target: the fleet never stops for good. Of 900 plants (seeds 1-5, 60 per kind, 8 orders)
    // 898 finish (session 32); the two that do not have single-vehicle blocks (README, "Traffic control: figures").
    context("every order finishes or is unroutable") {
        val kinds = listOf("one-way lanes" to oneWay, "one-way and two-way lanes" to mixed, "two-way lanes" to twoWay)
        withData(nameFn = { it.first }, kinds) { (_, lanes) ->
            forRandomRuns(lanes, seed = 2_222, iterations = 40) { orders ->
                ordersFinished + ordersUnroutable shouldBe orders
                doubleAllocations shouldBe 0
                sharedPositions shouldBe 0
            }
        }
    }

    // The other half, not met yet: of 60 random plants per kind (TrafficScoreBenchmark, seed 77, 8 orders), 52
    // one-way, 53 mixed and 55 two-way ones finish without a deadlock report (session 32); in the others the watchdog
    // reports one and breaks it. Enable it when the rule is complete.
    test("every order finishes or is unroutable, and the watchdog never fires").config(enabled = false) {
        forRandomRuns(mixed, seed = 2_222, iterations = 40) { orders ->
            ordersFinished + ordersUnroutable shouldBe orders
            deadlocksDetected shouldBe 0
        }
    }
})
