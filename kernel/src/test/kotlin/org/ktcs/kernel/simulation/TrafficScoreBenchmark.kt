package org.ktcs.kernel.simulation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.PropTestConfig
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.long
import io.kotest.property.checkAll
import org.ktcs.kernel.config.ConfigLoader

/**
 * How far the traffic rule gets on random small plants, per kind of lane: a benchmark, run only on request
 * (`KTCS_TRAFFIC_SCORE=60 ./mvnw -B verify -pl kernel -am -Dtest=TrafficScoreBenchmark
 * -Dsurefire.failIfNoSpecifiedTests=false`, with the number of plants per kind and seed; seed 77, or the seeds
 * `KTCS_TRAFFIC_SEEDS` names, e.g. `1-5`; 8 orders each). It prints, per kind, how many plants finished every order
 * without a deadlock report, how many had a report, and how many did not finish, and each plant that did not finish
 * (to run again with [SimulationRunner]); it fails only if a resource was held twice or two vehicles shared a point.
 */
class TrafficScoreBenchmark : FunSpec({
    val plantsPerKind = System.getenv("KTCS_TRAFFIC_SCORE")?.toIntOrNull()
    val kinds = listOf("one-way" to oneWay, "one-way and two-way" to mixed, "two-way" to twoWay)
    val seeds = System.getenv("KTCS_TRAFFIC_SEEDS")?.let { text ->
        val bounds = Regex("""(-?\d+)(?:-(-?\d+))?""").matchEntire(text.trim())
            ?: error("KTCS_TRAFFIC_SEEDS must be a seed or a range such as 1-5, not '$text'")
        bounds.groupValues[1].toLong()..(bounds.groupValues[2].ifEmpty { bounds.groupValues[1] }).toLong()
    } ?: 77L..77L

    test("random plants per kind of lane").config(enabled = plantsPerKind != null) {
        for ((kind, lanes) in kinds) {
            var clean = 0
            var reported = 0
            var unfinished = 0
            for (seed in seeds) {
                checkAll(
                    PropTestConfig(seed = seed, iterations = plantsPerKind!!),
                    trafficPlants(lanes),
                    Arb.int(ORDERS..ORDERS),
                    Arb.long(),
                ) { plant, orders, orderSeed ->
                    val config = ConfigLoader().load(null, emptyMap(), emptyList())
                    val report = SimulationRunner(plant.build(), config, listOf(stepVehicles), orders, orderSeed).run()
                    val finished = report.ordersFinished + report.ordersUnroutable == orders
                    if (finished && report.deadlocksDetected == 0) clean++
                    if (report.deadlocksDetected > 0) reported++
                    if (!finished) {
                        unfinished++
                        println("traffic score: did not finish: $plant, orders seed $orderSeed")
                    }
                    report.doubleAllocations shouldBe 0
                    report.sharedPositions shouldBe 0
                }
            }
            val plants = plantsPerKind!! * (seeds.last - seeds.first + 1)
            println(
                "traffic score, $kind lanes: $clean of $plants plants finished without a deadlock report; " +
                    "$reported with a report, $unfinished did not finish",
            )
        }
    }
}) {
    private companion object {
        const val ORDERS = 8
    }
}
