package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.filter
import io.kotest.property.checkAll

class PlantModelValidatorPropertyTest : FunSpec({
    test("generated valid models have no errors") {
        checkAll(500, Arb.validPlantModel()) { model ->
            model.errors().shouldBeEmpty()
        }
    }

    test("a generated model with its first path shortened to zero has exactly that one error") {
        checkAll(200, Arb.validPlantModel().filter { it.paths.isNotEmpty() }) { model ->
            val first = model.paths.first()
            val broken = model.copy(paths = listOf(first.copy(length = 0)) + model.paths.drop(1))

            broken.errors() shouldBe listOf(expectedError("path '${first.name}'", "length must be positive, was 0"))
        }
    }
})
