package org.ktcs.kernel.validation

import org.ktcs.api.model.Layer
import org.ktcs.api.model.PlantObject

private val RGB_COLOR = Regex("#[0-9A-Fa-f]{6}")

internal fun layoutProblems(index: ModelIndex): List<ModelProblem> =
    layerReferenceProblems(index) + layerGroupProblems(index) + colorProblems(index)

private fun layerReferenceProblems(index: ModelIndex): List<ModelProblem> {
    val model = index.model
    val references = model.points.map { it to it.layout.layerId } +
        model.paths.map { it to it.layout.layerId } +
        model.locations.map { it to it.layout.layerId }
    return references.mapNotNull { (element, layerId) ->
        element.errorIf(layerId !in index.layerIds) {
            "layer id $layerId names no layer of visual layout '${model.visualLayout.name}'"
        }
    }
}

private fun layerGroupProblems(index: ModelIndex): List<ModelProblem> = index.model.visualLayout.layers
    .filter { it.groupId !in index.layerGroupIds }
    .map { errorAt(it.label, "group id ${it.groupId} names no layer group") }

private val Layer.label: String get() = "layer '$name' (id $id)"

private fun colorProblems(index: ModelIndex): List<ModelProblem> =
    index.model.blocks.mapNotNull { it.badColor("color", it.layout.color) } +
        index.model.vehicles.mapNotNull { it.badColor("route color", it.layout.routeColor) }

private fun PlantObject.badColor(what: String, value: String): ModelProblem? =
    errorIf(!RGB_COLOR.matches(value)) { "$what must be #RRGGBB, was '$value'" }
