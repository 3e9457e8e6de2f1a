package org.ktcs.kernel.workingset

import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.event.LocationEvent
import org.ktcs.api.event.PathEvent
import org.ktcs.api.event.PlantModelReplacedEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.events.EventBus

/**
 * The plant as it is now: the loaded model plus what changed since (path and location locks, the vehicles' runtime
 * state). Every change is published as an event with the previous and current object. Confined to the kernel
 * context; [model] is an immutable snapshot that is rebuilt only when it is asked for after a change.
 */
class PlantState(initial: PlantModel, private val events: EventBus) {
    private var base = initial
    private val paths = LinkedHashMap<String, Path>()
    private val locations = LinkedHashMap<String, Location>()
    private val vehicles = LinkedHashMap<String, Vehicle>()
    private var snapshot: PlantModel? = null
    private var topologySnapshot: PlantModel? = null

    init {
        load(initial)
    }

    /** The current plant as one immutable model. */
    fun model(): PlantModel = snapshot ?: base.copy(
        paths = paths.values.toList(),
        locations = locations.values.toList(),
        vehicles = vehicles.values.toList(),
    ).also { snapshot = it }

    /**
     * The plant with the current path and location locks, but vehicles as loaded. Unlike [model] it changes only
     * when a lock does, so strategies and drivers can read it on every event without copying the plant each time.
     */
    fun topology(): PlantModel = topologySnapshot ?: base.copy(
        paths = paths.values.toList(),
        locations = locations.values.toList(),
    ).also { topologySnapshot = it }

    /** The model as loaded, without runtime changes: points, location types and blocks never change at runtime. */
    fun staticModel(): PlantModel = base

    fun vehicle(name: String): Vehicle = vehicles[name] ?: throw ObjectUnknownException("unknown vehicle '$name'")

    fun vehicleOrNull(name: String): Vehicle? = vehicles[name]

    fun vehicles(): Collection<Vehicle> = vehicles.values

    fun path(name: String): Path = paths[name] ?: throw ObjectUnknownException("unknown path '$name'")

    fun location(name: String): Location = locations[name] ?: throw ObjectUnknownException("unknown location '$name'")

    fun updateVehicle(name: String, change: (Vehicle) -> Vehicle): Vehicle {
        val previous = vehicle(name)
        val current = change(previous)
        if (current == previous) return previous
        check(current.name == name) { "a vehicle's name cannot change" }
        vehicles[name] = current
        snapshot = null
        events.publish(VehicleEvent(previous, current))
        return current
    }

    fun setPathLocked(name: String, locked: Boolean): Path {
        val previous = path(name)
        if (previous.locked == locked) return previous
        return previous.copy(locked = locked).also {
            paths[name] = it
            snapshot = null
            topologySnapshot = null
            events.publish(PathEvent(previous, it))
        }
    }

    fun setLocationLocked(name: String, locked: Boolean): Location {
        val previous = location(name)
        if (previous.locked == locked) return previous
        return previous.copy(locked = locked).also {
            locations[name] = it
            snapshot = null
            topologySnapshot = null
            events.publish(LocationEvent(previous, it))
        }
    }

    /** Replaces the whole plant. */
    fun replace(model: PlantModel) {
        load(model)
        events.publish(PlantModelReplacedEvent(model))
    }

    private fun load(model: PlantModel) {
        base = model
        paths.clear()
        locations.clear()
        vehicles.clear()
        model.paths.associateByTo(paths) { it.name }
        model.locations.associateByTo(locations) { it.name }
        model.vehicles.associateByTo(vehicles) { it.name }
        snapshot = model
        topologySnapshot = model
    }
}
