package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Point

class PointChecksTest : FunSpec({
    test("a point no path starts or ends at is only a warning") {
        val model = minimalPlant().copy(points = minimalPlant().points + Point("C"))

        model.problems() shouldBe listOf(expectedWarning("point 'C'", "is isolated: no path starts or ends here"))
        model.errors() shouldBe emptyList()
    }

    test("a point only reached by paths is not isolated") {
        val model = minimalPlant().mapBlocks { it.copy(members = setOf("B")) }

        model.problems() shouldBe emptyList()
    }

    test("a non-positive dimension of the max vehicle bounding box is an error") {
        val model = minimalPlant().mapPoints {
            if (it.name == "B") it.copy(maxVehicleBoundingBox = BoundingBox(height = 0)) else it
        }

        model.problems() shouldBe
            listOf(expectedError("point 'B'", "max vehicle bounding box height must be positive, was 0"))
    }
})
