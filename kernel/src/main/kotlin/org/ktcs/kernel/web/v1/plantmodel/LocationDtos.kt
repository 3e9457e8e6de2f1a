package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationLayout
import org.ktcs.api.model.LocationRepresentation
import org.ktcs.api.model.LocationType
import org.ktcs.api.model.LocationTypeLayout
import org.ktcs.kernel.web.v1.CoupleDto
import org.ktcs.kernel.web.v1.TripleDto
import org.ktcs.kernel.web.v1.parseEnum
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.toDomain
import org.ktcs.kernel.web.v1.toDto

@Serializable
data class LocationTypeDto(
    val name: String? = null,
    val allowedOperations: List<String> = emptyList(),
    val allowedPeripheralOperations: List<String> = emptyList(),
    val layout: LocationTypeLayoutDto = LocationTypeLayoutDto(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

@Serializable
data class LocationTypeLayoutDto(val locationRepresentation: String = "NONE")

@Serializable
data class LocationDto(
    val name: String? = null,
    val typeName: String? = null,
    val position: TripleDto = TripleDto(0, 0, 0),
    val links: List<LinkDto> = emptyList(),
    val locked: Boolean = false,
    val layout: LocationLayoutDto = LocationLayoutDto(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

@Serializable
data class LinkDto(val pointName: String? = null, val allowedOperations: List<String> = emptyList())

/** Where a location is drawn; [position] is written from the model position and ignored when read, as for points. */
@Serializable
data class LocationLayoutDto(
    val position: CoupleDto = CoupleDto(0, 0),
    val labelOffset: CoupleDto = CoupleDto(-10, -20),
    val locationRepresentation: String = "DEFAULT",
    val layerId: Int = 0,
)

fun LocationType.toDto(): LocationTypeDto = LocationTypeDto(
    name = name,
    allowedOperations = allowedOperations.toList(),
    allowedPeripheralOperations = allowedPeripheralOperations.toList(),
    layout = LocationTypeLayoutDto(layout.locationRepresentation.name),
    properties = properties.toPlantProperties(),
)

fun LocationTypeDto.toDomain(field: String): LocationType = LocationType(
    name = name.required("$field.name"),
    allowedOperations = allowedOperations.toSet(),
    allowedPeripheralOperations = allowedPeripheralOperations.toSet(),
    layout = LocationTypeLayout(representation(layout.locationRepresentation, "$field.layout")),
    properties = properties.toDomain("$field.properties"),
)

fun Location.toDto(): LocationDto = LocationDto(
    name = name,
    typeName = type,
    position = position.toDto(),
    links = links.map { LinkDto(it.point, it.allowedOperations.toList()) },
    locked = locked,
    layout = LocationLayoutDto(
        position = CoupleDto(position.x, position.y),
        labelOffset = layout.labelOffset.toDto(),
        locationRepresentation = layout.locationRepresentation.name,
        layerId = layout.layerId,
    ),
    properties = properties.toPlantProperties(),
)

fun LocationDto.toDomain(field: String): Location = Location(
    name = name.required("$field.name"),
    type = typeName.required("$field.typeName"),
    position = position.toDomain(),
    links = links.mapIndexed { i, link ->
        Link(link.pointName.required("$field.links[$i].pointName"), link.allowedOperations.toSet())
    },
    locked = locked,
    layout = LocationLayout(
        labelOffset = layout.labelOffset.toDomain(),
        locationRepresentation = representation(layout.locationRepresentation, "$field.layout"),
        layerId = layout.layerId,
    ),
    properties = properties.toDomain("$field.properties"),
)

private fun representation(value: String, layoutField: String) =
    parseEnum<LocationRepresentation>(value, "$layoutField.locationRepresentation")
