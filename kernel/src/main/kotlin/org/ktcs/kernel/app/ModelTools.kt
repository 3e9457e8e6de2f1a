package org.ktcs.kernel.app

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.persistence.ModelFileException
import org.ktcs.kernel.persistence.PlantModelFiles
import org.ktcs.kernel.simulation.TrafficGrid
import org.ktcs.kernel.simulation.WarehousePlant
import org.ktcs.kernel.validation.InvalidModelException
import org.ktcs.kernel.validation.ModelProblem
import org.ktcs.kernel.validation.PlantModelValidator
import java.io.PrintStream
import java.nio.file.Path

/** `ktcs model check` and `ktcs model convert`, for people deploying plants. */
class ModelTools(private val out: PrintStream) {
    /** Prints the summary and any warnings (exit 0), or every problem (exit 1). */
    fun check(file: Path): Int {
        val read = try {
            PlantModelFiles.readWithWarnings(file)
        } catch (error: ModelFileException) {
            out.println("error: ${error.message}")
            return Ktcs.EXIT_FAILURE
        }
        val model = read.model
        val problems = read.warnings + PlantModelValidator.validate(model)
        val errors = problems.filter { it.isError }
        if (errors.isNotEmpty()) {
            out.println("$file: ${errors.size} error(s), the model cannot be loaded")
            problems.forEach { out.println(it.line()) }
            return Ktcs.EXIT_FAILURE
        }
        out.println(model.summary())
        problems.forEach { out.println(it.line()) }
        return 0
    }

    /** Writes the generated [plant] to [output] as 7.0.0. */
    fun generate(plant: GeneratedPlant, output: Path): Int {
        val model = generated(plant)
        PlantModelFiles.write(model, output)
        out.println("wrote $output (version 7.0.0): ${model.summary()}")
        PlantModelValidator.validate(model).forEach { out.println(it.line()) }
        return 0
    }

    /** Reads [input] in any supported version and writes it as 7.0.0; refuses a model with errors. */
    fun convert(input: Path, output: Path): Int {
        val read = PlantModelFiles.readWithWarnings(input)
        val model = read.model
        val problems = read.warnings + PlantModelValidator.validate(model)
        if (problems.any { it.isError }) throw InvalidModelException(model.name, problems)
        PlantModelFiles.write(model, output)
        out.println("wrote $output (version 7.0.0): ${model.summary()}")
        problems.forEach { out.println(it.line()) }
        return 0
    }

    companion object {
        /** The model of a generated benchmark plant. */
        fun generated(plant: GeneratedPlant): PlantModel = when (plant.kind) {
            "grid" -> TrafficGrid(plant.width, plant.height, plant.vehicles).build()
            else -> WarehousePlant(plant.width, plant.height, plant.vehicles).build()
        }
    }
}

internal fun ModelProblem.line(): String = "${severity.name.lowercase()}: $element: $message"

/** One line for the launcher: the first error, and how many more there are. */
internal fun InvalidModelException.summaryLine(): String {
    val errors = problems.filter { it.isError }
    val more = if (errors.size > 1) " (and ${errors.size - 1} more; 'ktcs model check FILE' lists them all)" else ""
    return "invalid plant model '$modelName': ${errors.first().let { "${it.element}: ${it.message}" }}$more"
}
