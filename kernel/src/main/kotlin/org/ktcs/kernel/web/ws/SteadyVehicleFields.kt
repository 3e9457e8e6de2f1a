package org.ktcs.kernel.web.ws

import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.kernel.web.v1.events.parseColor
import org.ktcs.kernel.web.v1.toWire
import java.time.Instant

/**
 * The JSON values of the fields of a vehicle that seldom change, each with the object it was made of. A driving
 * vehicle is a new [Vehicle] many times a second that shares these objects with the one before (`copy` keeps them),
 * so they are encoded again only when one of them is another object ([of]).
 */
internal class SteadyVehicleFields private constructor(
    val name: Encoded<String>,
    val properties: Encoded<Map<String, String>>,
    val boundingBox: Encoded<BoundingBox>,
    val energyLevelThresholdSet: Encoded<EnergyLevelThresholdSet>,
    val loadHandlingDevices: Encoded<List<LoadHandlingDevice>>,
    val acceptableOrderTypes: Encoded<Set<AcceptableOrderType>>,
    val layout: Encoded<VehicleLayout>,
    val stateTimestamp: Encoded<Instant>,
    val procStateTimestamp: Encoded<Instant>,
) {
    /** The bytes of all values together. */
    val size: Int = listOf(
        name, properties, boundingBox, energyLevelThresholdSet, loadHandlingDevices, acceptableOrderTypes, layout,
        stateTimestamp, procStateTimestamp,
    ).sumOf { it.bytes.size }

    private fun isOf(vehicle: Vehicle): Boolean = name.source === vehicle.name &&
        properties.source === vehicle.properties &&
        boundingBox.source === vehicle.boundingBox &&
        energyLevelThresholdSet.source === vehicle.energyLevelThresholdSet &&
        loadHandlingDevices.source === vehicle.loadHandlingDevices &&
        acceptableOrderTypes.source === vehicle.acceptableOrderTypes &&
        layout.source === vehicle.layout &&
        stateTimestamp.source === vehicle.stateTimestamp &&
        procStateTimestamp.source === vehicle.procStateTimestamp

    companion object {
        /** [vehicle]'s values, reusing those of [last] (the same vehicle's, encoded before) that are of its objects. */
        fun of(vehicle: Vehicle, last: SteadyVehicleFields?): SteadyVehicleFields {
            if (last != null && last.isOf(vehicle)) return last
            return SteadyVehicleFields(
                last?.name.reusedFor(vehicle.name, ::jsonString),
                last?.properties.reusedFor(vehicle.properties, ::properties),
                last?.boundingBox.reusedFor(vehicle.boundingBox, ::boundingBox),
                last?.energyLevelThresholdSet.reusedFor(vehicle.energyLevelThresholdSet, ::thresholds),
                last?.loadHandlingDevices.reusedFor(vehicle.loadHandlingDevices, ::loadHandlingDevices),
                last?.acceptableOrderTypes.reusedFor(vehicle.acceptableOrderTypes, ::acceptableOrderTypes),
                last?.layout.reusedFor(vehicle.layout, ::layout),
                last?.stateTimestamp.reusedFor(vehicle.stateTimestamp, ::timestamp),
                last?.procStateTimestamp.reusedFor(vehicle.procStateTimestamp, ::timestamp),
            )
        }
    }
}

/** [bytes], the JSON of [source]. */
internal class Encoded<T : Any>(val source: T, val bytes: ByteArray)

/** This if it is [source]'s JSON (the same object), else [source] encoded by [encode]. */
internal fun <T : Any> Encoded<T>?.reusedFor(source: T, encode: (T) -> ByteArray): Encoded<T> =
    if (this != null && this.source === source) this else Encoded(source, encode(source))

/** [properties] as a JSON object. */
internal fun properties(properties: Map<String, String>) = json { stringMap(properties) }

private fun boundingBox(box: BoundingBox) = utf8(
    """{"length":${box.length},"width":${box.width},"height":${box.height},""" +
        """"referenceOffset":{"x":${box.referenceOffset.x},"y":${box.referenceOffset.y}}}""",
)

private fun thresholds(set: EnergyLevelThresholdSet) = utf8(
    """{"energyLevelCritical":${set.critical},"energyLevelGood":${set.good},""" +
        """"energyLevelFullyRecharged":${set.fullyRecharged},""" +
        """"energyLevelSufficientlyRecharged":${set.sufficientlyRecharged}}""",
)

private fun loadHandlingDevices(devices: List<LoadHandlingDevice>) = json {
    array(devices) {
        raw("""{"label":""")
        string(it.label)
        raw(""","full":${it.full}}""")
    }
}

private fun acceptableOrderTypes(types: Set<AcceptableOrderType>) = json {
    array(types) {
        raw("""{"name":""")
        string(it.name)
        raw(""","priority":${it.priority}}""")
    }
}

private fun layout(layout: VehicleLayout) = parseColor(layout.routeColor).let {
    utf8("""{"routeColor":{"red":${it.red},"green":${it.green},"blue":${it.blue}}}""")
}

/** [instant] as the JSON string v1 writes for it. */
internal fun timestamp(instant: Instant) = jsonString(instant.toWire())
