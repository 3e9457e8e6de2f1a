package org.ktcs.kernel.routing

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.booleans.shouldBeFalse
import io.kotest.matchers.booleans.shouldBeTrue
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple

class BoundingBoxesTest : FunSpec({
    val limit = BoundingBox(length = 1000, width = 800, height = 1500)

    test("a box does not protrude beyond itself or a larger one") {
        limit.protrudesBeyond(limit).shouldBeFalse()
        BoundingBox(900, 700, 1000).protrudesBeyond(limit).shouldBeFalse()
    }

    test("a box that is longer, wider or taller protrudes") {
        BoundingBox(1001, 800, 1500).protrudesBeyond(limit).shouldBeTrue()
        BoundingBox(1000, 801, 1500).protrudesBeyond(limit).shouldBeTrue()
        BoundingBox(1000, 800, 1501).protrudesBeyond(limit).shouldBeTrue()
    }

    test("a smaller box protrudes when its reference offset shifts it past a side") {
        BoundingBox(800, 800, 1500, referenceOffset = Couple(150, 0)).protrudesBeyond(limit).shouldBeTrue()
        BoundingBox(800, 800, 1500, referenceOffset = Couple(100, 0)).protrudesBeyond(limit).shouldBeFalse()
        BoundingBox(1000, 600, 1500, referenceOffset = Couple(0, -150)).protrudesBeyond(limit).shouldBeTrue()
    }
})
