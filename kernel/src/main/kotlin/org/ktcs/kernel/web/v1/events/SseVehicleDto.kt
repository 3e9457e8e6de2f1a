package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.HistoryEntry
import org.ktcs.kernel.web.v1.AcceptableOrderTypeDto
import org.ktcs.kernel.web.v1.BoundingBoxDto
import org.ktcs.kernel.web.v1.NanAsStringSerializer
import org.ktcs.kernel.web.v1.ObjectHistoryDto
import org.ktcs.kernel.web.v1.TripleDto
import org.ktcs.kernel.web.v1.toDto
import org.ktcs.kernel.web.v1.toWire
import org.ktcs.kernel.web.v1.vehicles.toDto

/** A vehicle in an SSE event: openTCS's full vehicle object, with state and proc state carrying their timestamps. */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
data class SseVehicleDto(
    val name: String,
    val properties: Map<String, String>,
    val history: ObjectHistoryDto,
    val boundingBox: BoundingBoxDto,
    val energyLevelThresholdSet: SseEnergyLevelThresholdSetDto,
    val energyLevel: Int,
    val maxVelocity: Int,
    val maxReverseVelocity: Int,
    val rechargeOperation: String,
    val loadHandlingDevices: List<SseLoadHandlingDeviceDto>,
    val state: SseVehicleStateDto,
    val procState: SseProcStateDto,
    val integrationLevel: String,
    val paused: Boolean,
    val transportOrder: String?,
    val orderSequence: String?,
    val acceptableOrderTypes: List<AcceptableOrderTypeDto>,
    val claimedResources: List<List<String>>,
    val allocatedResources: List<List<String>>,
    val currentPosition: String?,
    val pose: SsePoseDto,
    val envelopeKey: String?,
    val layout: SseVehicleLayoutDto,
    /** kTCS only: why the vehicle takes no orders; left out of the JSON when `null`, as in openTCS. */
    @EncodeDefault(EncodeDefault.Mode.NEVER)
    val waitingReason: String? = null,
)

@Serializable
data class SseEnergyLevelThresholdSetDto(
    val energyLevelCritical: Int,
    val energyLevelGood: Int,
    val energyLevelFullyRecharged: Int,
    val energyLevelSufficientlyRecharged: Int,
)

@Serializable
data class SseLoadHandlingDeviceDto(val label: String, val full: Boolean)

@Serializable
data class SseVehicleStateDto(val state: String, val timestamp: String)

@Serializable
data class SseProcStateDto(val procState: String, val timestamp: String)

@Serializable
data class SsePoseDto(
    val position: TripleDto?,
    @Serializable(with = NanAsStringSerializer::class) val orientationAngle: Double,
)

@Serializable
data class SseVehicleLayoutDto(val routeColor: SseColorDto)

@Serializable
data class SseColorDto(val red: Int, val green: Int, val blue: Int)

/**
 * kTCS keeps no history for vehicles, so it is always empty. The WebSocket stream writes the same JSON without this
 * DTO (`ws/VehicleJsonWriter.kt`); its test compares the two byte for byte, so a field added here fails it until the
 * writer writes it too.
 */
fun Vehicle.toSseDto(): SseVehicleDto = SseVehicleDto(
    name = name,
    properties = properties,
    history = emptyList<HistoryEntry>().toDto(),
    boundingBox = boundingBox.toDto(),
    energyLevelThresholdSet = energyLevelThresholdSet.let {
        SseEnergyLevelThresholdSetDto(it.critical, it.good, it.fullyRecharged, it.sufficientlyRecharged)
    },
    energyLevel = energyLevel,
    maxVelocity = maxVelocity,
    maxReverseVelocity = maxReverseVelocity,
    rechargeOperation = rechargeOperation,
    loadHandlingDevices = loadHandlingDevices.map { SseLoadHandlingDeviceDto(it.label, it.full) },
    state = SseVehicleStateDto(state.name, stateTimestamp.toWire()),
    procState = SseProcStateDto(procState.name, procStateTimestamp.toWire()),
    integrationLevel = integrationLevel.name,
    paused = paused,
    transportOrder = transportOrder,
    orderSequence = orderSequence,
    acceptableOrderTypes = acceptableOrderTypes.map { it.toDto() },
    claimedResources = claimedResources.map { it.toList() },
    allocatedResources = allocatedResources.map { it.toList() },
    currentPosition = currentPosition,
    pose = SsePoseDto(precisePosition?.toDto(), orientationAngle),
    envelopeKey = envelopeKey,
    layout = SseVehicleLayoutDto(parseColor(layout.routeColor)),
    waitingReason = waitingReason,
)

/** `#RRGGBB` as its components. */
internal fun parseColor(hex: String): SseColorDto {
    val rgb = hex.removePrefix("#").toInt(HEX)
    return SseColorDto(rgb shr 16 and 0xFF, rgb shr 8 and 0xFF, rgb and 0xFF)
}

private const val HEX = 16
