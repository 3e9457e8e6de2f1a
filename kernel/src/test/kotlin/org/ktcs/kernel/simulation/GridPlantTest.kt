package org.ktcs.kernel.simulation

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withData
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.routing.DefaultRouter
import org.ktcs.kernel.validation.PlantModelValidator

class GridPlantTest : FunSpec({
    context("a generated grid is a valid plant in which every station reaches every other") {
        withData(2 to 2, 5 to 3, 6 to 4, 7 to 7) { (width, height) ->
            val model = GridPlant(width, height).build()
            PlantModelValidator.validate(model).filter { it.isError }.shouldBeEmpty()
            val router = DefaultRouter().also { it.updateTopology(model) }
            val stationPoints = model.locations.map { it.links.single().point }
            val vehicle = Vehicle("probe")
            stationPoints.forEach { from ->
                stationPoints.filter { it != from }.forEach { to ->
                    router.routes(vehicle, from, to).size shouldBe 1
                }
            }
        }
    }

    test("a 40x40 grid has transfer stations, chargers and parking bays") {
        val model = GridPlant(40, 40).build()
        model.locations.count { it.type == GridPlant.TRANSFER_TYPE } shouldBe 40
        model.locations.count { it.type == GridPlant.RECHARGE_TYPE } shouldBe 10
        model.points.count { it.type == PointType.PARK_POSITION } shouldBe 39 + 29
    }

    test("refuses grids smaller than 2x2") {
        shouldThrow<IllegalArgumentException> { GridPlant(1, 5) }.message shouldBe
            "a grid needs at least 2×2 crossings, got 1x5"
    }

    test("a fleet is placed on park positions first, each vehicle on its own point") {
        val model = Fleet.withVehicles(GridPlant(6, 6).build(), 12)
        val starts = model.vehicles.map { it.properties.getValue(Fleet.INITIAL_POSITION) }
        starts.toSet().size shouldBe 12
        starts.take(5).forEach { model.point(it)!!.type shouldBe PointType.PARK_POSITION }
    }
})
