package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PeripheralOperation

private const val PATH = "path 'A --- B'"

class PathChecksTest : FunSpec({
    test("an unknown source point is an error, and leaves the old source isolated") {
        val model = minimalPlant().mapPaths { it.copy(sourcePoint = "X") }

        model.problems() shouldContainExactlyInAnyOrder listOf(
            expectedError(PATH, "source point 'X' does not exist"),
            expectedWarning("point 'A'", "is isolated: no path starts or ends here"),
        )
    }

    test("an unknown destination point is an error") {
        val model = minimalPlant().mapPaths { it.copy(destinationPoint = "Y") }

        model.errors() shouldBe listOf(expectedError(PATH, "destination point 'Y' does not exist"))
    }

    test("a zero length is an error") {
        val model = minimalPlant().mapPaths { it.copy(length = 0) }

        model.problems() shouldBe listOf(expectedError(PATH, "length must be positive, was 0"))
    }

    test("a negative length is an error") {
        val model = minimalPlant().mapPaths { it.copy(length = -5) }

        model.problems() shouldBe listOf(expectedError(PATH, "length must be positive, was -5"))
    }

    test("a negative maxVelocity is an error") {
        val model = minimalPlant().mapPaths { it.copy(maxVelocity = -1) }

        model.problems() shouldBe listOf(expectedError(PATH, "maxVelocity must not be negative, was -1"))
    }

    test("a negative maxReverseVelocity is an error") {
        val model = minimalPlant().mapPaths { it.copy(maxReverseVelocity = -2) }

        model.problems() shouldBe listOf(expectedError(PATH, "maxReverseVelocity must not be negative, was -2"))
    }

    test("a path navigable in neither direction is only a warning") {
        val model = minimalPlant().mapPaths { it.copy(maxVelocity = 0, maxReverseVelocity = 0) }

        model.problems() shouldBe listOf(
            expectedWarning(PATH, "is navigable in neither direction: maxVelocity and maxReverseVelocity are 0"),
        )
    }

    test("a path navigable only in reverse is fine") {
        minimalPlant().mapPaths { it.copy(maxVelocity = 0, maxReverseVelocity = 500) }.problems().shouldBeEmpty()
    }

    test("a peripheral operation at a known location is fine") {
        val model = minimalPlant().mapPaths {
            it.copy(peripheralOperations = listOf(PeripheralOperation("OPEN", "Station")))
        }

        model.problems().shouldBeEmpty()
    }

    test("a peripheral operation at an unknown location is an error") {
        val model = minimalPlant().mapPaths {
            it.copy(peripheralOperations = listOf(PeripheralOperation("OPEN", "Door")))
        }

        model.problems() shouldBe
            listOf(expectedError(PATH, "peripheral operation 'OPEN' names unknown location 'Door'"))
    }
})
