package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withTests
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Layer
import org.ktcs.api.model.LayerGroup
import org.ktcs.api.model.VisualLayout

class LayoutChecksTest : FunSpec({
    test("elements on any layer of the layout are fine") {
        val layout = VisualLayout(
            layers = listOf(Layer(0, 0, true, "Ground", 0), Layer(3, 1, true, "Upper", 1)),
            layerGroups = listOf(LayerGroup(0, "Main", true), LayerGroup(1, "Extra", false)),
        )
        val model = minimalPlant().copy(visualLayout = layout).mapPaths {
            it.copy(layout = it.layout.copy(layerId = 3))
        }

        model.problems().shouldBeEmpty()
    }

    test("a point on an unknown layer is an error") {
        val model = minimalPlant().mapPoints {
            if (it.name == "A") {
                it.copy(layout = it.layout.copy(layerId = 7))
            } else {
                it
            }
        }

        model.problems() shouldBe
            listOf(expectedError("point 'A'", "layer id 7 names no layer of visual layout 'VLayout'"))
    }

    test("a path on an unknown layer is an error") {
        val model = minimalPlant().mapPaths { it.copy(layout = it.layout.copy(layerId = 1)) }

        model.problems() shouldBe
            listOf(expectedError("path 'A --- B'", "layer id 1 names no layer of visual layout 'VLayout'"))
    }

    test("a location on an unknown layer is an error") {
        val model = minimalPlant().mapLocations { it.copy(layout = it.layout.copy(layerId = -1)) }

        model.problems() shouldBe
            listOf(expectedError("location 'Station'", "layer id -1 names no layer of visual layout 'VLayout'"))
    }

    test("a layer in an unknown layer group is an error") {
        val model = minimalPlant().copy(visualLayout = VisualLayout(layers = listOf(Layer(0, 0, true, "Ground", 4))))

        model.problems() shouldBe listOf(expectedError("layer 'Ground' (id 0)", "group id 4 names no layer group"))
    }

    context("colours") {
        test("upper- and lower-case hex digits are fine") {
            minimalPlant()
                .mapBlocks { it.copy(layout = it.layout.copy(color = "#a0B1c2")) }
                .mapVehicles { it.copy(layout = it.layout.copy(routeColor = "#FFFFFF")) }
                .problems().shouldBeEmpty()
        }

        withTests(nameFn = { "block colour '$it' is an error" }, "red", "#FFF", "FF0000", "#GG0000", "#FF00000", "") {
            minimalPlant().mapBlocks { block -> block.copy(layout = block.layout.copy(color = it)) }.problems() shouldBe
                listOf(expectedError("block 'Block-01'", "color must be #RRGGBB, was '$it'"))
        }

        test("a vehicle route colour not in #RRGGBB form is an error") {
            minimalPlant().mapVehicles { it.copy(layout = it.layout.copy(routeColor = "#00FF00 ")) }.problems() shouldBe
                listOf(expectedError("vehicle 'Vehicle-01'", "route color must be #RRGGBB, was '#00FF00 '"))
        }
    }
})
