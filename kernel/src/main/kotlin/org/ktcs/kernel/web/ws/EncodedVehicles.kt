package org.ktcs.kernel.web.ws

import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.web.LastEncoded

/**
 * Vehicles' event states as UTF-8 JSON, written by [VehicleJsonWriter], their resource lists copied in as bytes. A
 * driving vehicle changes many times a second while the resources it claimed for its route (most of its JSON on a
 * large plant) stay the same list, and a client that keeps the latest state leaves them out when they did not change
 * (`omitUnchanged`): each list ([EncodedResourceLists]) is made only when a client takes it. The values of the fields
 * that seldom change ([SteadyVehicleFields]) are kept for the [capacity] most recently changed vehicles.
 */
internal class EncodedVehicles(capacity: Int) {
    private val claimed = EncodedResourceLists(capacity)
    private val allocated = EncodedResourceLists(capacity)
    private val steady = LastEncoded<Vehicle, SteadyVehicleFields>(capacity, ::steadyFieldsOf)

    fun marked(vehicle: Vehicle): MarkedJson = VehicleJsonWriter(
        vehicle,
        steady.of(vehicle.name, vehicle),
        lazy { claimed.of(vehicle.name, vehicle.claimedResources) },
        lazy { allocated.of(vehicle.name, vehicle.allocatedResources) },
    )

    private fun steadyFieldsOf(vehicle: Vehicle): SteadyVehicleFields =
        SteadyVehicleFields.of(vehicle, steady.lastOf(vehicle.name))
}

/** An object's state as UTF-8 JSON, whole or without some of its top-level fields. */
internal interface MarkedJson {
    /** The whole object. */
    val full: ByteArray

    /** The object without its top-level [fields]. */
    fun without(fields: List<String>): ByteArray

    /** The object with only its top-level [fields], those it leaves out while they are `null` written as `null`. */
    fun only(fields: List<String>): ByteArray
}
