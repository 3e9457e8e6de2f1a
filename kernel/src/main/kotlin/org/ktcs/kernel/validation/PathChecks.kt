package org.ktcs.kernel.validation

import org.ktcs.api.model.Path
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.api.model.PlantModel

internal fun pathProblems(index: ModelIndex): List<ModelProblem> =
    index.model.paths.flatMap { pathProblems(it, index.model) }

private fun pathProblems(path: Path, model: PlantModel): List<ModelProblem> = listOfNotNull(
    unknownPoint(path, "source", path.sourcePoint, model),
    unknownPoint(path, "destination", path.destinationPoint, model),
    path.errorIf(path.length <= 0) { "length must be positive, was ${path.length}" },
    path.negativeVelocity("maxVelocity", path.maxVelocity),
    path.negativeVelocity("maxReverseVelocity", path.maxReverseVelocity),
    path.warningIf(path.maxVelocity == 0 && path.maxReverseVelocity == 0) {
        "is navigable in neither direction: maxVelocity and maxReverseVelocity are 0"
    },
) + path.peripheralOperations.mapNotNull { unknownLocation(path, it, model) }

private fun unknownPoint(path: Path, end: String, point: String, model: PlantModel): ModelProblem? =
    path.errorIf(model.point(point) == null) { "$end point '$point' does not exist" }

private fun unknownLocation(path: Path, operation: PeripheralOperation, model: PlantModel): ModelProblem? =
    path.errorIf(model.location(operation.location) == null) {
        "peripheral operation '${operation.operation}' names unknown location '${operation.location}'"
    }
