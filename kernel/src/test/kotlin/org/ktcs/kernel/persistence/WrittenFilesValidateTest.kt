package org.ktcs.kernel.persistence

import io.kotest.core.spec.style.FunSpec

/** Whatever kTCS writes must be a valid 7.0.0 file for openTCS, whatever version it was read from. */
class WrittenFilesValidateTest : FunSpec({
    for (resource in PersistenceFixtures.openTcsModels + PersistenceFixtures.HANDWRITTEN_V002) {
        test("${resource.substringAfter("plant-models/")} re-written validates against model-7.0.0.xsd") {
            val model = PlantModelFiles.read(PersistenceFixtures.path(resource))
            PersistenceFixtures.validate(PlantModelFiles.writeToString(model))
        }
    }

    test("every openTCS fixture is valid against the schema of its own version") {
        for (resource in PersistenceFixtures.openTcsModels) {
            val version = Regex(
                """<model version="([\d.]+)"""",
            ).find(PersistenceFixtures.text(resource))!!.groupValues[1]
            PersistenceFixtures.validate(PersistenceFixtures.text(resource), PersistenceFixtures.schema(version))
        }
    }
})
