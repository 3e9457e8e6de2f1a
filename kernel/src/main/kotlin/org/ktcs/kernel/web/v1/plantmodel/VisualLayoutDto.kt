package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.Layer
import org.ktcs.api.model.LayerGroup
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.web.v1.required

@Serializable
data class VisualLayoutDto(
    val name: String? = null,
    val scaleX: Double = 50.0,
    val scaleY: Double = 50.0,
    val layers: List<LayerDto> = emptyList(),
    val layerGroups: List<LayerGroupDto> = emptyList(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

@Serializable
data class LayerDto(val id: Int, val ordinal: Int, val visible: Boolean, val name: String, val groupId: Int)

@Serializable
data class LayerGroupDto(val id: Int, val name: String, val visible: Boolean)

fun VisualLayout.toDto(): VisualLayoutDto = VisualLayoutDto(
    name = name,
    scaleX = scaleX,
    scaleY = scaleY,
    layers = layers.map { LayerDto(it.id, it.ordinal, it.visible, it.name, it.groupId) },
    layerGroups = layerGroups.map { LayerGroupDto(it.id, it.name, it.visible) },
    properties = properties.toPlantProperties(),
)

/** Absent layers fall back to kTCS's single default layer and group. */
fun VisualLayoutDto.toDomain(field: String): VisualLayout {
    val defaults = VisualLayout()
    return VisualLayout(
        name = name.required("$field.name"),
        scaleX = scaleX,
        scaleY = scaleY,
        layers = layers.map { Layer(it.id, it.ordinal, it.visible, it.name, it.groupId) }.ifEmpty { defaults.layers },
        layerGroups = layerGroups.map { LayerGroup(it.id, it.name, it.visible) }.ifEmpty { defaults.layerGroups },
        properties = properties.toDomain("$field.properties"),
    )
}
