package org.ktcs.kernel.app

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.persistence.ModelFileException
import org.ktcs.kernel.persistence.ModelRead
import org.ktcs.kernel.persistence.PlantModelFiles
import org.ktcs.kernel.persistence.PublishedModelFile
import org.ktcs.kernel.validation.InvalidModelException
import org.ktcs.kernel.validation.ModelProblem
import org.ktcs.kernel.validation.PlantModelValidator
import java.nio.file.Path

/** A model that passed validation, with the warnings it still has. */
data class LoadedModel(val model: PlantModel, val source: String, val warnings: List<ModelProblem>)

/** Reads a plant-model file (or the demo plant) and refuses it if it has errors. */
object PlantModelLoader {
    /** The demo plant shipped inside the kernel. */
    const val DEMO_RESOURCE = "/org/ktcs/kernel/demo/ktcs-demo.xml"

    fun load(file: Path?): LoadedModel = if (file == null) {
        loadDemo()
    } else {
        validated(PlantModelFiles.readWithWarnings(file), file.toString())
    }

    /**
     * The model a kTCS start runs: [file] when given (`--model`), else the model last published to [published]
     * (`PUT /v1/plantModel` or the overview's modelling mode), else the demo plant.
     */
    fun loadAtStart(file: Path?, published: PublishedModelFile): LoadedModel = when {
        file != null -> load(file)

        published.exists() -> try {
            validated(PlantModelFiles.readWithWarnings(published.file), "published model ${published.file}")
        } catch (error: ModelFileException) {
            throw ModelFileException(
                "${error.message} (the published model; the one published before it is ${published.backup}; " +
                    "start with --model FILE, or move the file away to start with the demo plant)",
                error,
            )
        }

        else -> loadDemo()
    }

    fun loadDemo(): LoadedModel {
        val stream = PlantModelLoader::class.java.getResourceAsStream(DEMO_RESOURCE)
            ?: error("the demo plant $DEMO_RESOURCE is missing from the kernel jar")
        return stream.use { validated(PlantModelFiles.readWithWarnings(it, "demo plant"), "demo plant") }
    }

    /** The reader's warnings come first: they say what the file held that the model no longer does. */
    private fun validated(read: ModelRead, source: String): LoadedModel {
        val problems = read.warnings + PlantModelValidator.validate(read.model)
        if (problems.any { it.isError }) throw InvalidModelException(read.model.name, problems)
        return LoadedModel(read.model, source, problems)
    }
}
