package org.ktcs.kernel.simulation

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType
import org.ktcs.kernel.routing.DefaultRouter
import org.ktcs.kernel.validation.PlantModelValidator

class TrafficGridTest : FunSpec({
    fun PlantModel.everyStationReachesEveryOther() {
        PlantModelValidator.validate(this).filter { it.isError }.shouldBeEmpty()
        val router = DefaultRouter().also { it.updateTopology(this) }
        val stations = locations.map { it.links.single().point }
        val vehicle = vehicles.first()
        for (from in stations) {
            for (to in stations.filter { it != from }) {
                router.routes(vehicle, from, to).size shouldBe
                    1
            }
        }
    }

    context("generated traffic grids are valid and every station reaches every other") {
        withData(3 to 3, 5 to 4, 10 to 10, 7 to 12) { (width, height) ->
            TrafficGrid(width, height, 4).build().everyStationReachesEveryOther()
        }
    }

    test(
        "a 20x20 grid as issue #11 describes it: 2 m apart, a counter-clockwise ring, a station every 4th border point",
    ) {
        val model = TrafficGrid(20, 20, 30).build()
        model.points.count { it.type == PointType.HALT_POSITION } shouldBe 400
        model.points.count { it.type == PointType.PARK_POSITION } shouldBe 30
        model.locations.size shouldBe 76 / 4
        model.path("P-00-00 --- P-01-00")!!.length shouldBe 2000
        // Counter-clockwise: east along the bottom, north on the right, west along the top, south on the left.
        listOf("P-18-00 --- P-19-00", "P-19-18 --- P-19-19", "P-01-19 --- P-00-19", "P-00-01 --- P-00-00")
            .forEach { model.path(it)!!.maxReverseVelocity shouldBe 0 }
        model.vehicles.map { it.boundingBox.length to it.maxVelocity }.toSet() shouldBe setOf(1000L to 1000)
        model.vehicles.map { it.properties[Fleet.INITIAL_POSITION] }.toSet().size shouldBe 30
    }

    test("warehouses are valid and every dead-end station reaches every other") {
        WarehousePlant(3, 6, 4).build().everyStationReachesEveryOther()
    }

    test("a plant without room for the fleet is refused with a reason") {
        shouldThrow<IllegalArgumentException> { TrafficGrid(3, 3, 9) }.message shouldBe
            "a 3x3 traffic grid has room for 8 park bays, not 9 vehicles"
    }
})
