package org.ktcs.kernel.simulation

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.config.ConfigLoader

/**
 * Small warehouses (two-way aisles, stations and park bays at the end of dead-end stubs) finish every order: a vehicle
 * held back is sent into a free park bay, judged by its way into the bay only (it turns back there, so the bay is a
 * stop of its claim), no two retreats share a bay, and the grant that sends it back out is never freed under it.
 */
class WarehouseTrafficTest : FunSpec({
    // Main at the start of round 13 stalled in each of these (22, 23 and 1 of 40 orders finished).
    withData(
        nameFn = { (vehicles, seed) -> "3x6 warehouse, $vehicles vehicles, 40 orders, seed $seed" },
        4 to 1L,
        4 to 3L,
        6 to 1L,
    ) { (vehicles, seed) ->
        val config = ConfigLoader().load(null, emptyMap(), emptyList())
        val plant = WarehousePlant(3, 6, vehicles).build()
        val report = SimulationRunner(plant, config, listOf(stepVehicles), ORDERS, seed).run()
        withClue(report.lines().joinToString("\n")) {
            report.ordersFinished shouldBe ORDERS
            report.doubleAllocations shouldBe 0
            report.sharedPositions shouldBe 0
        }
    }
})

private const val ORDERS = 40
