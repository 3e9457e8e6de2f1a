package org.ktcs.adapters.vda5050

import io.kotest.assertions.nondeterministic.eventually
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.jsonPrimitive
import kotlin.time.Duration.Companion.seconds

/**
 * Two VDA 5050 vehicles sent along the same paths, crossing each other's way: every order finishes, and after every
 * vehicle event no resource is allocated to both and no point holds both.
 */
class Vda5050ContentionTest : FunSpec({
    val plant = VdaPlant(listOf("Point-0001", "Point-0027"))
    val violations = exclusivityViolations(plant.application.kernel)
    afterSpec { plant.close() }

    test("two vehicles contending for a path: every order finishes, nothing is allocated twice") {
        eventually(20.seconds) {
            (0..1).forEach { plant.vehicle(it)["state"]!!.jsonPrimitive.content shouldBe "IDLE" }
        }
        val trips = listOf(
            "Storage 01" to "Load cargo",
            "Goods out 01" to "Unload cargo",
            "Storage 02" to "Load cargo",
            "Goods out 02" to "Unload cargo",
        )
        repeat(2) { round ->
            plant.order("A$round", trips[round % 4].first, trips[round % 4].second, plant.vehicleName(0))
            plant.order("B$round", trips[(round + 1) % 4].first, trips[(round + 1) % 4].second, plant.vehicleName(1))
        }
        eventually(120.seconds) {
            (0..1).forEach { round ->
                plant.orderState("A$round") shouldBe "FINISHED"
                plant.orderState("B$round") shouldBe "FINISHED"
            }
        }
        violations.shouldBeEmpty()
    }
})
