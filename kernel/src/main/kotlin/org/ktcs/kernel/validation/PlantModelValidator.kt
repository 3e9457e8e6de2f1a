package org.ktcs.kernel.validation

import org.ktcs.api.model.PlantModel

/**
 * Checks a plant model for semantic mistakes its types cannot rule out: clashing or blank names, references to
 * objects, layers or layer groups that do not exist, values openTCS rejects (non-positive path lengths, negative
 * velocities, energy thresholds out of order, non-positive bounding boxes, malformed colours), and link operations a
 * location type does not allow.
 *
 * Errors make a model unusable; warnings flag what is legal but probably a mistake: isolated points, unreachable
 * locations, paths navigable in neither direction, unknown envelope keys, empty blocks, unused location types.
 *
 * The work is linear in the size of the model.
 */
object PlantModelValidator {
    private val checks: List<(ModelIndex) -> List<ModelProblem>> = listOf(
        ::nameProblems,
        ::pointProblems,
        ::pathProblems,
        ::locationTypeProblems,
        ::locationProblems,
        ::blockProblems,
        ::vehicleProblems,
        ::layoutProblems,
        ::trafficProblems,
    )

    /** Every problem of [model], errors and warnings, grouped by kind of check and in model order within each. */
    fun validate(model: PlantModel): List<ModelProblem> {
        val index = ModelIndex(model)
        return checks.flatMap { check -> check(index) }
    }

    /** The warnings about places in [model] where vehicles cannot be kept from blocking each other for good. */
    fun trafficWarnings(model: PlantModel): List<ModelProblem> = trafficProblems(ModelIndex(model))

    /**
     * Returns the warnings of [model].
     *
     * @throws InvalidModelException if the model has any error.
     */
    fun requireValid(model: PlantModel): List<ModelProblem> {
        val problems = validate(model)
        if (problems.any { it.isError }) throw InvalidModelException(model.name, problems)
        return problems
    }
}
