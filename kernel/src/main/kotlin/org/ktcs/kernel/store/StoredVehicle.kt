package org.ktcs.kernel.store

import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Position
import org.ktcs.api.model.Vehicle

/**
 * What the store keeps of a vehicle between runs: what an operator or its driver set, and where it was last. The
 * rest (state, allocations, route) is rebuilt when the kernel starts.
 */
data class StoredVehicle(
    val name: String,
    val integrationLevel: IntegrationLevel,
    val paused: Boolean,
    val energyLevelThresholdSet: EnergyLevelThresholdSet,
    val acceptableOrderTypes: Set<AcceptableOrderType>,
    val envelopeKey: String?,
    val currentPosition: String?,
    val precisePosition: Position?,
    val energyLevel: Int,
    val driver: String?,
) {
    /** [vehicle] with the values kept here that an operator or the last run set (not the integration level). */
    fun applyTo(vehicle: Vehicle): Vehicle = vehicle.copy(
        paused = paused,
        energyLevelThresholdSet = energyLevelThresholdSet,
        acceptableOrderTypes = acceptableOrderTypes,
        envelopeKey = envelopeKey,
        currentPosition = currentPosition,
        precisePosition = precisePosition,
        energyLevel = energyLevel,
    )

    companion object {
        fun of(vehicle: Vehicle, driver: String?) = StoredVehicle(
            name = vehicle.name,
            integrationLevel = vehicle.integrationLevel,
            paused = vehicle.paused,
            energyLevelThresholdSet = vehicle.energyLevelThresholdSet,
            acceptableOrderTypes = vehicle.acceptableOrderTypes,
            envelopeKey = vehicle.envelopeKey,
            currentPosition = vehicle.currentPosition,
            precisePosition = vehicle.precisePosition,
            energyLevel = vehicle.energyLevel,
            driver = driver,
        )
    }
}

/** A path or location lock; [kind] is `path` or `location`. */
data class StoredLock(val kind: String, val locked: Boolean) {
    companion object {
        const val PATH = "path"
        const val LOCATION = "location"
    }
}

/** Where the name generator was: the millisecond and counter of the last name it completed. */
data class NamePosition(val millis: Long, val counter: Long)
