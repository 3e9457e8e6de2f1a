package org.ktcs.kernel.workingset

import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle

/** The plant as it is now, read-only: what code outside the kernel's core may see of [PlantState]. */
interface PlantView {
    /** The current plant as one immutable model. */
    fun model(): PlantModel

    /**
     * The plant's layout with the current path and location locks; its vehicles are as loaded, not as they are now
     * (use [model] or [vehicle] for those). Safe to read from any thread.
     */
    fun layoutWithLocks(): PlantModel

    /** The vehicle [name] as it is now, or null if there is none; safe to read from any thread. */
    fun publishedVehicle(name: String): Vehicle?

    /** The vehicles as they are now, in no particular order; safe to read from any thread. */
    fun publishedVehicles(): Collection<Vehicle>

    /** The model as loaded, without runtime changes: points, location types and blocks never change at runtime. */
    fun staticModel(): PlantModel

    fun vehicle(name: String): Vehicle

    fun vehicleOrNull(name: String): Vehicle?

    fun vehicles(): Collection<Vehicle>

    fun path(name: String): Path

    fun location(name: String): Location
}
