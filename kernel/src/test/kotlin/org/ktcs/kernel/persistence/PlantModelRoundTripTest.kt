package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.checkAll

/** Writing a model and reading it back gives the same model, and what is written is valid 7.0.0. */
class PlantModelRoundTripTest : FunSpec({
    test("read(write(model)) is the model, for anything 7.0.0 can express") {
        checkAll(300, PlantModelArbs.plantModel) { model ->
            val text = PlantModelFiles.writeToString(model)
            PlantModelFiles.read(text.byteInputStream(), "generated.xml") shouldBe model
        }
    }

    test("every generated model is written as a valid 7.0.0 file") {
        checkAll(300, PlantModelArbs.plantModel) { model ->
            PersistenceFixtures.validate(PlantModelFiles.writeToString(model))
        }
    }
})
