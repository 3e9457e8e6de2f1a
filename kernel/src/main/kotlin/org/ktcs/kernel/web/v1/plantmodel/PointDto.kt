package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.Envelope
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointLayout
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Pose
import org.ktcs.kernel.web.v1.BoundingBoxDto
import org.ktcs.kernel.web.v1.CoupleDto
import org.ktcs.kernel.web.v1.NanAsStringSerializer
import org.ktcs.kernel.web.v1.TripleDto
import org.ktcs.kernel.web.v1.parseEnum
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.toDomain
import org.ktcs.kernel.web.v1.toDto

@Serializable
data class PointDto(
    val name: String? = null,
    val position: TripleDto = TripleDto(0, 0, 0),
    @Serializable(with = NanAsStringSerializer::class) val vehicleOrientationAngle: Double = Double.NaN,
    val type: String = "HALT_POSITION",
    val layout: PointLayoutDto = PointLayoutDto(),
    val vehicleEnvelopes: List<EnvelopeDto> = emptyList(),
    val maxVehicleBoundingBox: BoundingBoxDto = BoundingBoxDto(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

/**
 * Where a point is drawn. kTCS draws a point at its model position, so [position] is written from it and ignored when
 * read.
 */
@Serializable
data class PointLayoutDto(
    val position: CoupleDto = CoupleDto(0, 0),
    val labelOffset: CoupleDto = CoupleDto(-10, -20),
    val layerId: Int = 0,
)

/** An envelope of a point or path; openTCS writes the envelope key as `key`. */
@Serializable
data class EnvelopeDto(val key: String? = null, val vertices: List<CoupleDto> = emptyList())

fun Map<String, Envelope>.toEnvelopeDtos(): List<EnvelopeDto> =
    map { (key, envelope) -> EnvelopeDto(key, envelope.vertices.map { it.toDto() }) }

fun List<EnvelopeDto>.toDomain(field: String): Map<String, Envelope> = withIndex().associate { (i, envelope) ->
    envelope.key.required("$field[$i].key") to Envelope(envelope.vertices.map { it.toDomain() })
}

fun Point.toDto(): PointDto = PointDto(
    name = name,
    position = pose.position.toDto(),
    vehicleOrientationAngle = pose.orientationAngle,
    type = type.name,
    layout = PointLayoutDto(CoupleDto(pose.position.x, pose.position.y), layout.labelOffset.toDto(), layout.layerId),
    vehicleEnvelopes = vehicleEnvelopes.toEnvelopeDtos(),
    maxVehicleBoundingBox = maxVehicleBoundingBox.toDto(),
    properties = properties.toPlantProperties(),
)

fun PointDto.toDomain(field: String): Point = Point(
    name = name.required("$field.name"),
    pose = Pose(position.toDomain(), vehicleOrientationAngle),
    type = parseEnum<PointType>(type, "$field.type"),
    maxVehicleBoundingBox = maxVehicleBoundingBox.toDomain(),
    vehicleEnvelopes = vehicleEnvelopes.toDomain("$field.vehicleEnvelopes"),
    layout = PointLayout(layout.labelOffset.toDomain(), layout.layerId),
    properties = properties.toDomain("$field.properties"),
)
