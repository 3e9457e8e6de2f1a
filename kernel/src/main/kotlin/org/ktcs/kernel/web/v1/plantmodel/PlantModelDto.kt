package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.web.v1.required

/**
 * The plant model of `GET /plantModel` and `PUT /plantModel`. In a PUT body only names and the ends of paths are
 * required; everything else falls back to openTCS's defaults.
 */
@Serializable
data class PlantModelDto(
    val name: String? = null,
    val points: List<PointDto> = emptyList(),
    val paths: List<PathDto> = emptyList(),
    val locationTypes: List<LocationTypeDto> = emptyList(),
    val locations: List<LocationDto> = emptyList(),
    val blocks: List<BlockDto> = emptyList(),
    val vehicles: List<PlantVehicleDto> = emptyList(),
    val visualLayout: VisualLayoutDto? = null,
    val properties: List<PlantPropertyDto> = emptyList(),
)

/** A property as the v1 plant model writes it: `{name, value}`, unlike the `{key, value}` of orders. */
@Serializable
data class PlantPropertyDto(val name: String? = null, val value: String? = null)

fun Map<String, String>.toPlantProperties(): List<PlantPropertyDto> = map { (k, v) -> PlantPropertyDto(k, v) }

fun List<PlantPropertyDto>.toDomain(field: String): Map<String, String> = withIndex().associate { (i, property) ->
    property.name.required("$field[$i].name") to property.value.required("$field[$i].value")
}

fun PlantModel.toDto(): PlantModelDto = PlantModelDto(
    name = name,
    points = points.map { it.toDto() },
    paths = paths.map { it.toDto() },
    locationTypes = locationTypes.map { it.toDto() },
    locations = locations.map { it.toDto() },
    blocks = blocks.map { it.toDto() },
    vehicles = vehicles.map { it.toDto() },
    visualLayout = visualLayout.toDto(),
    properties = properties.toPlantProperties(),
)

fun PlantModelDto.toDomain(): PlantModel = PlantModel(
    name = name.required("name"),
    points = points.mapIndexed { i, point -> point.toDomain("points[$i]") },
    paths = paths.mapIndexed { i, path -> path.toDomain("paths[$i]") },
    vehicles = vehicles.mapIndexed { i, vehicle -> vehicle.toDomain("vehicles[$i]") },
    locationTypes = locationTypes.mapIndexed { i, type -> type.toDomain("locationTypes[$i]") },
    locations = locations.mapIndexed { i, location -> location.toDomain("locations[$i]") },
    blocks = blocks.mapIndexed { i, block -> block.toDomain("blocks[$i]") },
    visualLayout = visualLayout?.toDomain("visualLayout") ?: VisualLayout(),
    properties = properties.toDomain("properties"),
)
