package org.ktcs.kernel.validation

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.model.Block
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point

class PlantModelValidatorTest : FunSpec({
    test("the minimal plant has no problems") {
        minimalPlant().problems().shouldBeEmpty()
    }

    test("an empty plant has no problems") {
        PlantModel("empty").problems().shouldBeEmpty()
    }

    test("a problem prints as one line naming severity, element and message") {
        expectedError("path 'A --- B'", "length must be positive, was 0").toString() shouldBe
            "ERROR path 'A --- B': length must be positive, was 0"
    }

    test("requireValid returns the warnings of a model without errors") {
        val model = minimalPlant().mapBlocks { it.copy(members = emptySet()) }

        PlantModelValidator.requireValid(model) shouldBe listOf(expectedWarning("block 'Block-01'", "has no members"))
    }

    test("requireValid throws with every error listed below a summary line") {
        val model = minimalPlant()
            .mapPaths { it.copy(length = 0, maxVelocity = -1) }
            .mapBlocks { it.copy(members = emptySet()) }

        val thrown = shouldThrow<InvalidModelException> { PlantModelValidator.requireValid(model) }

        thrown.message shouldBe """
            plant model 'minimal' has 2 errors:
              ERROR path 'A --- B': length must be positive, was 0
              ERROR path 'A --- B': maxVelocity must not be negative, was -1
        """.trimIndent()
        thrown.problems.size shouldBe 3
    }

    test("the exception message says error in the singular for one error") {
        val model = minimalPlant().mapPaths { it.copy(length = 0) }

        shouldThrow<InvalidModelException> { PlantModelValidator.requireValid(model) }
            .message shouldContain "plant model 'minimal' has 1 error:\n"
    }

    test("a large ring plant whose block holds every point has no problems") {
        val size = 10_000
        val points = List(size) { Point("P$it") }
        val paths = List(size) { Path("Path-$it", "P$it", "P${(it + 1) % size}") }
        val blocks = listOf(Block("Everything", members = points.map { it.name }.toSet()))

        PlantModel("large", points = points, paths = paths, blocks = blocks).problems().shouldBeEmpty()
    }
})
