package org.ktcs.kernel.web.ws

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Position
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.kernel.web.ws.VehicleField.ACCEPTABLE_ORDER_TYPES
import org.ktcs.kernel.web.ws.VehicleField.ALLOCATED_RESOURCES
import org.ktcs.kernel.web.ws.VehicleField.BOUNDING_BOX
import org.ktcs.kernel.web.ws.VehicleField.CLAIMED_RESOURCES
import org.ktcs.kernel.web.ws.VehicleField.CURRENT_POSITION
import org.ktcs.kernel.web.ws.VehicleField.ENERGY_LEVEL
import org.ktcs.kernel.web.ws.VehicleField.ENERGY_LEVEL_THRESHOLD_SET
import org.ktcs.kernel.web.ws.VehicleField.ENVELOPE_KEY
import org.ktcs.kernel.web.ws.VehicleField.HISTORY
import org.ktcs.kernel.web.ws.VehicleField.INTEGRATION_LEVEL
import org.ktcs.kernel.web.ws.VehicleField.LAYOUT
import org.ktcs.kernel.web.ws.VehicleField.LOAD_HANDLING_DEVICES
import org.ktcs.kernel.web.ws.VehicleField.MAX_REVERSE_VELOCITY
import org.ktcs.kernel.web.ws.VehicleField.MAX_VELOCITY
import org.ktcs.kernel.web.ws.VehicleField.NAME
import org.ktcs.kernel.web.ws.VehicleField.ORDER_SEQUENCE
import org.ktcs.kernel.web.ws.VehicleField.PAUSED
import org.ktcs.kernel.web.ws.VehicleField.PROPERTIES
import org.ktcs.kernel.web.ws.VehicleField.RECHARGE_OPERATION
import org.ktcs.kernel.web.ws.VehicleField.STATE
import org.ktcs.kernel.web.ws.VehicleField.TRANSPORT_ORDER
import org.ktcs.kernel.web.ws.VehicleField.WAITING_REASON

/**
 * A vehicle's event state as UTF-8 JSON, written field by field straight from the [Vehicle]: byte for byte what
 * [org.ktcs.kernel.web.v1.V1Json] writes for [org.ktcs.kernel.web.v1.events.toSseDto], without building the DTOs,
 * encoding them to a string and turning that into bytes, which cost the web server more CPU than anything else while
 * many vehicles drive. The values that seldom change are copied from [steady], the resource lists from [claimed] and
 * [allocated] (asked for only when written). Each result is a new array made to its size (the fields are measured
 * first), so one instance serves several threads.
 */
internal class VehicleJsonWriter(
    private val vehicle: Vehicle,
    private val steady: SteadyVehicleFields,
    private val claimed: Lazy<ByteArray>,
    private val allocated: Lazy<ByteArray>,
) : FieldByFieldJson<VehicleField>(VehicleField.FIELDS) {
    override fun isPresent(field: VehicleField) = field != WAITING_REASON || vehicle.waitingReason != null

    override fun writeValue(field: VehicleField, out: Utf8JsonOut) = when (field.kind) {
        VehicleFieldKind.BYTES -> out.raw(bytesOf(field))
        VehicleFieldKind.TEXT -> out.stringOrNull(textOf(field))
        VehicleFieldKind.NUMBER -> out.int(numberOf(field))
        VehicleFieldKind.STATE -> out.state(field, stateNameOf(field), sinceOf(field))
        VehicleFieldKind.POSE -> out.pose(vehicle)
    }

    override fun sizeOfValue(field: VehicleField): Int = when (field.kind) {
        VehicleFieldKind.BYTES -> bytesOf(field).size
        VehicleFieldKind.TEXT -> textOf(field)?.let { Utf8JsonOut.sizeOf(it) } ?: Utf8JsonOut.NULL.size
        VehicleFieldKind.NUMBER -> Utf8JsonOut.sizeOf(numberOf(field).toLong())
        VehicleFieldKind.STATE -> stateSize(field, stateNameOf(field), sinceOf(field))
        VehicleFieldKind.POSE -> poseSize(vehicle)
    }

    private fun bytesOf(field: VehicleField): ByteArray = when (field) {
        NAME -> steady.name.bytes
        PROPERTIES -> steady.properties.bytes
        HISTORY -> EMPTY_HISTORY
        BOUNDING_BOX -> steady.boundingBox.bytes
        ENERGY_LEVEL_THRESHOLD_SET -> steady.energyLevelThresholdSet.bytes
        LOAD_HANDLING_DEVICES -> steady.loadHandlingDevices.bytes
        INTEGRATION_LEVEL -> INTEGRATION_LEVELS[vehicle.integrationLevel.ordinal]
        PAUSED -> Utf8JsonOut.booleanOf(vehicle.paused)
        ACCEPTABLE_ORDER_TYPES -> steady.acceptableOrderTypes.bytes
        CLAIMED_RESOURCES -> claimed.value
        ALLOCATED_RESOURCES -> allocated.value
        LAYOUT -> steady.layout.bytes
        else -> error("$field is no kept value")
    }

    private fun textOf(field: VehicleField): String? = when (field) {
        RECHARGE_OPERATION -> vehicle.rechargeOperation
        TRANSPORT_ORDER -> vehicle.transportOrder
        ORDER_SEQUENCE -> vehicle.orderSequence
        CURRENT_POSITION -> vehicle.currentPosition
        ENVELOPE_KEY -> vehicle.envelopeKey
        WAITING_REASON -> vehicle.waitingReason
        else -> error("$field is no string")
    }

    private fun numberOf(field: VehicleField): Int = when (field) {
        ENERGY_LEVEL -> vehicle.energyLevel
        MAX_VELOCITY -> vehicle.maxVelocity
        MAX_REVERSE_VELOCITY -> vehicle.maxReverseVelocity
        else -> error("$field is no number")
    }

    private fun stateNameOf(field: VehicleField) =
        if (field == STATE) VEHICLE_STATES[vehicle.state.ordinal] else PROC_STATES[vehicle.procState.ordinal]

    private fun sinceOf(field: VehicleField) =
        if (field == STATE) steady.stateTimestamp.bytes else steady.procStateTimestamp.bytes
}

/** How a field's value is made: kept as bytes, a string or `null`, an int, a state with its timestamp, the pose. */
internal enum class VehicleFieldKind { BYTES, TEXT, NUMBER, STATE, POSE }

/** The top-level fields of [org.ktcs.kernel.web.v1.events.SseVehicleDto], in its order. */
internal enum class VehicleField(val wireName: String, val kind: VehicleFieldKind) {
    NAME("name", VehicleFieldKind.BYTES),
    PROPERTIES("properties", VehicleFieldKind.BYTES),
    HISTORY("history", VehicleFieldKind.BYTES),
    BOUNDING_BOX("boundingBox", VehicleFieldKind.BYTES),
    ENERGY_LEVEL_THRESHOLD_SET("energyLevelThresholdSet", VehicleFieldKind.BYTES),
    ENERGY_LEVEL("energyLevel", VehicleFieldKind.NUMBER),
    MAX_VELOCITY("maxVelocity", VehicleFieldKind.NUMBER),
    MAX_REVERSE_VELOCITY("maxReverseVelocity", VehicleFieldKind.NUMBER),
    RECHARGE_OPERATION("rechargeOperation", VehicleFieldKind.TEXT),
    LOAD_HANDLING_DEVICES("loadHandlingDevices", VehicleFieldKind.BYTES),
    STATE("state", VehicleFieldKind.STATE),
    PROC_STATE("procState", VehicleFieldKind.STATE),
    INTEGRATION_LEVEL("integrationLevel", VehicleFieldKind.BYTES),
    PAUSED("paused", VehicleFieldKind.BYTES),
    TRANSPORT_ORDER("transportOrder", VehicleFieldKind.TEXT),
    ORDER_SEQUENCE("orderSequence", VehicleFieldKind.TEXT),
    ACCEPTABLE_ORDER_TYPES("acceptableOrderTypes", VehicleFieldKind.BYTES),
    CLAIMED_RESOURCES("claimedResources", VehicleFieldKind.BYTES),
    ALLOCATED_RESOURCES("allocatedResources", VehicleFieldKind.BYTES),
    CURRENT_POSITION("currentPosition", VehicleFieldKind.TEXT),
    POSE("pose", VehicleFieldKind.POSE),
    ENVELOPE_KEY("envelopeKey", VehicleFieldKind.TEXT),
    LAYOUT("layout", VehicleFieldKind.BYTES),
    WAITING_REASON("waitingReason", VehicleFieldKind.TEXT),
    ;

    companion object {
        val FIELDS = JsonFields(entries.toTypedArray(), VehicleField::wireName)
    }
}

private val EMPTY_HISTORY = utf8("""{"entries":[]}""")
private val VEHICLE_STATES = VehicleState.entries.map { jsonString(it.name) }
private val PROC_STATES = ProcState.entries.map { jsonString(it.name) }
private val INTEGRATION_LEVELS = IntegrationLevel.entries.map { jsonString(it.name) }
private val TIMESTAMP = utf8(""","timestamp":""")
private val POSITION_START = utf8("""{"position":""")
private val X = utf8("""{"x":""")
private val Y = utf8(""","y":""")
private val Z = utf8(""","z":""")

// `{"x":`, `,"y":`, `,"z":` and `}`.
private val POSITION_NAMES_SIZE = X.size + Y.size + Z.size + 1
private val ORIENTATION_ANGLE = utf8(""","orientationAngle":""")
private val NAN = utf8("\"NaN\"")
private const val OPEN_BRACE = '{'.code.toByte()
private const val CLOSE_BRACE = '}'.code.toByte()

/**
 * `{"state":"IDLE","timestamp":…}` for [field] `state`, and the same with `procState`: its value's field is named as
 * the field itself.
 */
private fun Utf8JsonOut.state(field: VehicleField, name: ByteArray, since: ByteArray) {
    byte(OPEN_BRACE)
    raw(VehicleField.FIELDS.keyOf(field))
    raw(name)
    raw(TIMESTAMP)
    raw(since)
    byte(CLOSE_BRACE)
}

private fun stateSize(field: VehicleField, name: ByteArray, since: ByteArray) =
    1 + VehicleField.FIELDS.keyOf(field).size + name.size + TIMESTAMP.size + since.size + 1

/** The pose, its unknown orientation (`NaN`) as a string, as [org.ktcs.kernel.web.v1.NanAsStringSerializer] does. */
private fun Utf8JsonOut.pose(vehicle: Vehicle) {
    raw(POSITION_START)
    val position = vehicle.precisePosition
    if (position == null) {
        raw(Utf8JsonOut.NULL)
    } else {
        raw(X)
        long(position.x)
        raw(Y)
        long(position.y)
        raw(Z)
        long(position.z)
        byte(CLOSE_BRACE)
    }
    raw(ORIENTATION_ANGLE)
    val angle = vehicle.orientationAngle
    if (angle.isNaN()) raw(NAN) else double(angle)
    byte(CLOSE_BRACE)
}

private fun poseSize(vehicle: Vehicle) = POSITION_START.size + positionSize(vehicle.precisePosition) +
    ORIENTATION_ANGLE.size + angleSize(vehicle.orientationAngle) + 1

private fun positionSize(position: Position?) = if (position == null) {
    Utf8JsonOut.NULL.size
} else {
    POSITION_NAMES_SIZE + Utf8JsonOut.sizeOf(position.x) + Utf8JsonOut.sizeOf(position.y) +
        Utf8JsonOut.sizeOf(position.z)
}

private fun angleSize(angle: Double) = if (angle.isNaN()) NAN.size else Utf8JsonOut.sizeOf(angle)
