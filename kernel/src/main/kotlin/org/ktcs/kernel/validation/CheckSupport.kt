package org.ktcs.kernel.validation

import org.ktcs.api.model.Block
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantObject
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle

internal fun errorAt(element: String, message: String) = ModelProblem(Severity.ERROR, element, message)

internal fun PlantObject.error(message: String) = errorAt(label, message)

internal fun PlantObject.warning(message: String) = ModelProblem(Severity.WARNING, label, message)

internal inline fun PlantObject.errorIf(condition: Boolean, message: () -> String): ModelProblem? =
    if (condition) errorAt(label, message()) else null

internal inline fun PlantObject.warningIf(condition: Boolean, message: () -> String): ModelProblem? =
    if (condition) warning(message()) else null

/** The object as a problem names it: its kind, then its quoted name. */
internal val PlantObject.label: String get() = "$kind '$name'"

internal val PlantObject.kind: String
    get() = when (this) {
        is Point -> "point"
        is Path -> "path"
        is Location -> "location"
        is LocationType -> "location type"
        is Block -> "block"
        is Vehicle -> "vehicle"
    }

internal fun PlantObject.negativeVelocity(field: String, value: Int): ModelProblem? =
    errorIf(value < 0) { "$field must not be negative, was $value" }

/** openTCS rejects boxes with a dimension that is not positive, for vehicles and for points alike. */
internal fun PlantObject.boundingBoxProblems(what: String, box: BoundingBox): List<ModelProblem> =
    listOf("length" to box.length, "width" to box.width, "height" to box.height)
        .mapNotNull { (dimension, value) -> errorIf(value <= 0) { "$what $dimension must be positive, was $value" } }
