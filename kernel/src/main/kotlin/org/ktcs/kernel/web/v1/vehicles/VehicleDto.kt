package org.ktcs.kernel.web.v1.vehicles

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.web.v1.AcceptableOrderTypeDto
import org.ktcs.kernel.web.v1.BoundingBoxDto
import org.ktcs.kernel.web.v1.NanAsStringSerializer
import org.ktcs.kernel.web.v1.TripleDto
import org.ktcs.kernel.web.v1.toDto
import org.ktcs.kernel.web.v1.toWire

/**
 * A vehicle as `GET /vehicles/{NAME}` answers it. Unlike orders, v1 writes a vehicle's properties as a JSON object;
 * [length] repeats the bounding box's length (deprecated in openTCS).
 */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
data class VehicleDto(
    val name: String,
    val properties: Map<String, String>,
    val length: Long,
    val boundingBox: BoundingBoxDto,
    val energyLevelGood: Int,
    val energyLevelCritical: Int,
    val energyLevelSufficientlyRecharged: Int,
    val energyLevelFullyRecharged: Int,
    val energyLevel: Int,
    val integrationLevel: String,
    val paused: Boolean,
    val procState: String,
    val procStateTimestamp: String,
    val transportOrder: String?,
    val currentPosition: String?,
    val precisePosition: TripleDto?,
    @Serializable(with = NanAsStringSerializer::class) val orientationAngle: Double,
    val state: String,
    val stateTimestamp: String,
    val allocatedResources: List<List<String>>,
    val claimedResources: List<List<String>>,
    val allowedOrderTypes: List<String>,
    val acceptableOrderTypes: List<AcceptableOrderTypeDto>,
    val envelopeKey: String?,
    /** kTCS only: why the vehicle takes no orders; left out of the JSON when `null`, as in openTCS. */
    @EncodeDefault(EncodeDefault.Mode.NEVER)
    val waitingReason: String? = null,
)

fun Vehicle.toDto(): VehicleDto = VehicleDto(
    name = name,
    properties = properties,
    length = boundingBox.length,
    boundingBox = boundingBox.toDto(),
    energyLevelGood = energyLevelThresholdSet.good,
    energyLevelCritical = energyLevelThresholdSet.critical,
    energyLevelSufficientlyRecharged = energyLevelThresholdSet.sufficientlyRecharged,
    energyLevelFullyRecharged = energyLevelThresholdSet.fullyRecharged,
    energyLevel = energyLevel,
    integrationLevel = integrationLevel.name,
    paused = paused,
    procState = procState.name,
    procStateTimestamp = procStateTimestamp.toWire(),
    transportOrder = transportOrder,
    currentPosition = currentPosition,
    precisePosition = precisePosition?.toDto(),
    orientationAngle = orientationAngle,
    state = state.name,
    stateTimestamp = stateTimestamp.toWire(),
    allocatedResources = allocatedResources.map { it.toList() },
    claimedResources = claimedResources.map { it.toList() },
    allowedOrderTypes = allowedOrderTypes.toList(),
    acceptableOrderTypes = acceptableOrderTypes.map { it.toDto() },
    envelopeKey = envelopeKey,
    waitingReason = waitingReason,
)

fun AcceptableOrderType.toDto(): AcceptableOrderTypeDto = AcceptableOrderTypeDto(name, priority)
