package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Block
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Vehicle

class NameChecksTest : FunSpec({
    test("two points with one name clash") {
        val model = minimalPlant().mapPoints { it.copy(name = "A") }.mapPaths { it.copy(destinationPoint = "A") }

        model.problems() shouldBe listOf(expectedError("point 'A'", "name 'A' is used by 2 objects: point, point"))
    }

    test("names clash across kinds, and the problem names both kinds") {
        val model = minimalPlant().mapVehicles { it.copy(name = "A --- B") }

        model.problems() shouldBe
            listOf(expectedError("path 'A --- B'", "name 'A --- B' is used by 2 objects: path, vehicle"))
    }

    test("a location type and a block clash with a location") {
        val model = minimalPlant().copy(
            locationTypes = minimalPlant().locationTypes + LocationType("Station"),
            blocks = minimalPlant().blocks + Block("Station", members = setOf("B")),
        )

        model.errors() shouldBe listOf(
            expectedError(
                "location type 'Station'",
                "name 'Station' is used by 3 objects: location type, location, block",
            ),
        )
    }

    test("a blank name is an error, and blank names do not clash with each other") {
        val model = minimalPlant().copy(vehicles = listOf(Vehicle(" "), Vehicle(" ")))

        model.problems() shouldBe listOf(
            expectedError("vehicle ' '", "name must not be blank"),
            expectedError("vehicle ' '", "name must not be blank"),
        )
    }

    test("an empty name is an error") {
        val model = minimalPlant().mapBlocks { it.copy(name = "") }

        model.problems() shouldBe listOf(expectedError("block ''", "name must not be blank"))
    }
})
