package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle

/** Vehicles without a start point are placed on free park positions, else free points, never two on one. */
class LoopbackPlacementTest : FunSpec({
    val unplaced = LoopbackFixtures.vehicle().copy(properties = emptyMap())

    fun plant(vararg vehicles: Vehicle, parkAt: Set<String> = setOf("C")): PlantModel {
        val base = LoopbackFixtures.plant()
        return base.copy(
            points = base.points.map { if (it.name in parkAt) it.copy(type = PointType.PARK_POSITION) else it },
            vehicles = vehicles.toList(),
        )
    }

    fun enable(model: PlantModel, name: String, placement: Placement, others: Map<String, String> = emptyMap()) =
        FakeDriverContext(model, name).also { context ->
            context.otherPositions = others
            LoopbackDriver(name, context, LoopbackSettings(), placement).enable()
        }

    fun FakeDriverContext.position() = reportsOf<Report.PositionReport>().single().point

    test("a vehicle without a position goes to a free park position, and the operator is told how to pin it") {
        val context = enable(plant(unplaced), "V", Placement())
        context.position() shouldBe "C"
        val text = context.reportsOf<Report.Notification>().single().text
        text shouldContain "V had no position; placed it on the free park position C"
        text shouldContain "loopback:initialPosition=C"
    }

    test("vehicles enabled one after another get different points, park positions first") {
        val placement = Placement()
        val model = plant(unplaced, unplaced.copy(name = "W"), unplaced.copy(name = "X"), parkAt = setOf("C", "E"))
        listOf("V", "W", "X").map { enable(model, it, placement).position() } shouldBe listOf("C", "E", "A")
    }

    test("points other vehicles stand on or start at are not free") {
        val pinned = unplaced.copy(name = "P", properties = mapOf(LoopbackProperties.INITIAL_POSITION to "A"))
        val context = enable(plant(unplaced, pinned, parkAt = emptySet()), "V", Placement(), mapOf("R" to "B"))
        context.position() shouldBe "C"
    }

    test("with every point taken the vehicle stays unplaced, and the operator is told") {
        val taken = mapOf("1" to "A", "2" to "B", "3" to "C", "4" to "E", "5" to "S")
        val context = enable(plant(unplaced), "V", Placement(), taken)
        context.reportsOf<Report.PositionReport>() shouldBe emptyList()
        context.reportsOf<Report.Notification>().single().text shouldBe "V: no free point to place it on"
    }
})
