package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Link
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.PeripheralOperation

private const val STATION = "location 'Station'"

class LocationChecksTest : FunSpec({
    test("an unknown location type is an error, and leaves the old type unused") {
        val model = minimalPlant().mapLocations { it.copy(type = "Charger") }

        model.problems() shouldContainExactlyInAnyOrder listOf(
            expectedError(STATION, "location type 'Charger' does not exist"),
            expectedWarning("location type 'Transfer'", "is used by no location"),
        )
    }

    test("a link to an unknown point is an error") {
        val model = minimalPlant().mapLocations { it.copy(links = listOf(Link("Z"))) }

        model.problems() shouldBe listOf(expectedError(STATION, "link to unknown point 'Z'"))
    }

    test("a link may allow fewer operations than its location type, or leave them all allowed") {
        val model = minimalPlant().mapLocations { it.copy(links = listOf(Link("A", setOf("UNLOAD")), Link("B"))) }

        model.problems().shouldBeEmpty()
    }

    test("a link allowing operations its location type does not allow is an error") {
        val model = minimalPlant().mapLocations { it.copy(links = listOf(Link("A", setOf("LOAD", "PAINT", "DRILL")))) }

        model.problems() shouldBe listOf(
            expectedError(
                STATION,
                "link to point 'A' allows operations [DRILL, PAINT] that location type 'Transfer' does not allow",
            ),
        )
    }

    test("a location without links is only a warning") {
        val model = minimalPlant().mapLocations { it.copy(links = emptyList()) }

        model.problems() shouldBe listOf(expectedWarning(STATION, "is unreachable: it has no links to points"))
    }

    test("a peripheral location without links is fine, since paths operate it") {
        val model = minimalPlant()
            .mapLocations { it.copy(links = emptyList()) }
            .mapPaths { it.copy(peripheralOperations = listOf(PeripheralOperation("OPEN", "Station"))) }

        model.problems().shouldBeEmpty()
    }

    test("a location type no location uses is only a warning") {
        val model = minimalPlant().copy(locationTypes = minimalPlant().locationTypes + LocationType("Spare"))

        model.problems() shouldBe listOf(expectedWarning("location type 'Spare'", "is used by no location"))
    }
})
