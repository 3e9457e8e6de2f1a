package org.ktcs.kernel.web.v1.plantmodel

import kotlinx.serialization.Serializable
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.kernel.web.v1.BoundingBoxDto
import org.ktcs.kernel.web.v1.requirePercent
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.toDomain
import org.ktcs.kernel.web.v1.toDto

/** A vehicle as the plant model describes it; [length] is openTCS's deprecated copy of the bounding box length. */
@Serializable
data class PlantVehicleDto(
    val name: String? = null,
    val length: Long = 1000,
    val boundingBox: BoundingBoxDto? = null,
    val energyLevelCritical: Int = 30,
    val energyLevelGood: Int = 90,
    val energyLevelFullyRecharged: Int = 90,
    val energyLevelSufficientlyRecharged: Int = 30,
    val maxVelocity: Int = 1000,
    val maxReverseVelocity: Int = 1000,
    val envelopeKey: String? = null,
    val layout: VehicleLayoutDto = VehicleLayoutDto(),
    val properties: List<PlantPropertyDto> = emptyList(),
)

@Serializable
data class VehicleLayoutDto(val routeColor: String = "#00FF00")

fun Vehicle.toDto(): PlantVehicleDto = PlantVehicleDto(
    name = name,
    length = boundingBox.length,
    boundingBox = boundingBox.toDto(),
    energyLevelCritical = energyLevelThresholdSet.critical,
    energyLevelGood = energyLevelThresholdSet.good,
    energyLevelFullyRecharged = energyLevelThresholdSet.fullyRecharged,
    energyLevelSufficientlyRecharged = energyLevelThresholdSet.sufficientlyRecharged,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    envelopeKey = envelopeKey,
    layout = VehicleLayoutDto(layout.routeColor),
    properties = properties.toPlantProperties(),
)

/** Without a bounding box, the deprecated [PlantVehicleDto.length] sets the box's length. */
fun PlantVehicleDto.toDomain(field: String): Vehicle = Vehicle(
    name = name.required("$field.name"),
    energyLevelThresholdSet = thresholds(field),
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    boundingBox = boundingBox?.toDomain() ?: BoundingBox(length = length),
    envelopeKey = envelopeKey,
    layout = VehicleLayout(layout.routeColor),
    properties = properties.toDomain("$field.properties"),
)

private fun PlantVehicleDto.thresholds(field: String) = EnergyLevelThresholdSet(
    critical = requirePercent(energyLevelCritical, "$field.energyLevelCritical"),
    good = requirePercent(energyLevelGood, "$field.energyLevelGood"),
    sufficientlyRecharged = requirePercent(energyLevelSufficientlyRecharged, "$field.energyLevelSufficientlyRecharged"),
    fullyRecharged = requirePercent(energyLevelFullyRecharged, "$field.energyLevelFullyRecharged"),
)
