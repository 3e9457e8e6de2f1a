package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.ConnectionType
import org.ktcs.api.model.ExecutionTrigger
import org.ktcs.api.model.Path
import org.ktcs.api.model.PathLayout
import org.ktcs.api.model.PeripheralOperation
import org.ktcs.kernel.web.v1.CoupleDto
import org.ktcs.kernel.web.v1.parseEnum
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.toDomain
import org.ktcs.kernel.web.v1.toDto

/** A path; as in openTCS, velocities default to 0 (not navigable in that direction). */
@Serializable
data class PathDto(
    val name: String? = null,
    val srcPointName: String? = null,
    val destPointName: String? = null,
    val length: Long = 1,
    val maxVelocity: Int = 0,
    val maxReverseVelocity: Int = 0,
    val peripheralOperations: List<PeripheralOperationDto> = emptyList(),
    val locked: Boolean = false,
    val layout: PathLayoutDto = PathLayoutDto(),
    val vehicleEnvelopes: List<EnvelopeDto> = emptyList(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

@Serializable
data class PeripheralOperationDto(
    val operation: String? = null,
    val locationName: String? = null,
    val executionTrigger: String = "AFTER_ALLOCATION",
    val completionRequired: Boolean = false,
)

@Serializable
data class PathLayoutDto(
    val connectionType: String = "DIRECT",
    val controlPoints: List<CoupleDto> = emptyList(),
    val layerId: Int = 0,
)

fun Path.toDto(): PathDto = PathDto(
    name = name,
    srcPointName = sourcePoint,
    destPointName = destinationPoint,
    length = length,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    peripheralOperations = peripheralOperations.map { it.toDto() },
    locked = locked,
    layout = PathLayoutDto(layout.connectionType.name, layout.controlPoints.map { it.toDto() }, layout.layerId),
    vehicleEnvelopes = vehicleEnvelopes.toEnvelopeDtos(),
    properties = properties.toPlantProperties(),
)

fun PathDto.toDomain(field: String): Path = Path(
    name = name.required("$field.name"),
    sourcePoint = srcPointName.required("$field.srcPointName"),
    destinationPoint = destPointName.required("$field.destPointName"),
    length = length,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    peripheralOperations = peripheralOperations.mapIndexed { i, op -> op.toDomain("$field.peripheralOperations[$i]") },
    locked = locked,
    vehicleEnvelopes = vehicleEnvelopes.toDomain("$field.vehicleEnvelopes"),
    layout = layout.toDomain("$field.layout"),
    properties = properties.toDomain("$field.properties"),
)

private fun PeripheralOperation.toDto() =
    PeripheralOperationDto(operation, location, executionTrigger.name, completionRequired)

private fun PeripheralOperationDto.toDomain(field: String) = PeripheralOperation(
    operation = operation.required("$field.operation"),
    location = locationName.required("$field.locationName"),
    executionTrigger = parseEnum<ExecutionTrigger>(executionTrigger, "$field.executionTrigger"),
    completionRequired = completionRequired,
)

private fun PathLayoutDto.toDomain(field: String) = PathLayout(
    connectionType = parseEnum<ConnectionType>(connectionType, "$field.connectionType"),
    controlPoints = controlPoints.map { it.toDomain() },
    layerId = layerId,
)
