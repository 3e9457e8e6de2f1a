package org.ktcs.kernel.validation

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point

internal fun pointProblems(index: ModelIndex): List<ModelProblem> =
    index.model.points.flatMap { pointProblems(it, index.model) }

private fun pointProblems(point: Point, model: PlantModel): List<ModelProblem> =
    listOfNotNull(isolation(point, model)) +
        point.boundingBoxProblems("max vehicle bounding box", point.maxVehicleBoundingBox)

private fun isolation(point: Point, model: PlantModel): ModelProblem? = point.warningIf(
    model.outgoingPaths(point.name).isEmpty() && model.incomingPaths(point.name).isEmpty(),
) { "is isolated: no path starts or ends here" }
