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
import java.util.concurrent.ConcurrentHashMap

/**
 * The plant as it is now: the loaded model plus what changed since (path and location locks, the vehicles' runtime
 * state). Every change is published as an event with the previous and current object.
 *
 * Changes happen in the kernel context only, and most reads too; [model] is an immutable snapshot rebuilt only
 * when it is asked for after a change. Drivers read from their own threads, so what they read is published for any
 * thread: [layoutWithLocks] (rebuilt when a lock changes) and [publishedVehicle] / [publishedVehicles] (one
 * immutable [Vehicle] per name, replaced when it changes).
 */
class PlantState(initial: PlantModel, private val events: EventBus) : PlantView {
    private var base = initial
    private val paths = LinkedHashMap<String, Path>()
    private val locations = LinkedHashMap<String, Location>()
    private val vehicles = LinkedHashMap<String, Vehicle>()
    private val published = ConcurrentHashMap<String, Vehicle>()
    private var snapshot: PlantModel? = null

    @Volatile
    private var layout: PlantModel = initial

    init {
        load(initial)
    }

    /** The current plant as one immutable model. */
    override fun model(): PlantModel = snapshot ?: base.copy(
        paths = paths.values.toList(),
        locations = locations.values.toList(),
        vehicles = vehicles.values.toList(),
    ).also { snapshot = it }

    /**
     * The plant's layout with the current path and location locks; its vehicles are as loaded, not as they are now
     * (use [model] or [vehicle] for those). Unlike [model] it changes only when a lock does, so strategies and
     * drivers can read it on every event without copying the plant each time. Safe to read from any thread.
     */
    override fun layoutWithLocks(): PlantModel = layout

    /** The vehicle [name] as it is now, or null if there is none; safe to read from any thread. */
    override fun publishedVehicle(name: String): Vehicle? = published[name]

    /** The vehicles as they are now, in no particular order; safe to read from any thread. */
    override fun publishedVehicles(): Collection<Vehicle> = published.values

    /** The model as loaded, without runtime changes: points, location types and blocks never change at runtime. */
    override fun staticModel(): PlantModel = base

    override fun vehicle(name: String): Vehicle = vehicles[name] ?: throw ObjectUnknownException(
        "unknown vehicle '$name'",
    )

    override fun vehicleOrNull(name: String): Vehicle? = vehicles[name]

    override fun vehicles(): Collection<Vehicle> = vehicles.values

    override fun path(name: String): Path = paths[name] ?: throw ObjectUnknownException("unknown path '$name'")

    override fun location(name: String): Location = locations[name] ?: throw ObjectUnknownException(
        "unknown location '$name'",
    )

    fun updateVehicle(name: String, change: (Vehicle) -> Vehicle): Vehicle {
        events.assertConfined { "PlantState.updateVehicle" }
        val previous = vehicle(name)
        val current = change(previous)
        if (current == previous) return previous
        check(current.name == name) { "a vehicle's name cannot change" }
        vehicles[name] = current
        published[name] = current
        snapshot = null
        events.publish(VehicleEvent(previous, current))
        return current
    }

    fun setPathLocked(name: String, locked: Boolean): Path {
        events.assertConfined { "PlantState.setPathLocked" }
        val previous = path(name)
        if (previous.locked == locked) return previous
        return previous.copy(locked = locked).also {
            paths[name] = it
            lockChanged()
            events.publish(PathEvent(previous, it))
        }
    }

    fun setLocationLocked(name: String, locked: Boolean): Location {
        events.assertConfined { "PlantState.setLocationLocked" }
        val previous = location(name)
        if (previous.locked == locked) return previous
        return previous.copy(locked = locked).also {
            locations[name] = it
            lockChanged()
            events.publish(LocationEvent(previous, it))
        }
    }

    /** Takes the new versions of paths and locations whose locks or velocities changed; vehicles stay as they are. */
    fun apply(change: TopologyChange) {
        events.assertConfined { "PlantState.apply" }
        for (path in change.paths) {
            val previous = path(path.name)
            paths[path.name] = path
            events.publish(PathEvent(previous, path))
        }
        for (location in change.locations) {
            val previous = location(location.name)
            locations[location.name] = location
            events.publish(LocationEvent(previous, location))
        }
        base = base.copy(paths = paths.values.toList(), locations = locations.values.toList())
        lockChanged()
    }

    /** Replaces the whole plant. */
    fun replace(model: PlantModel) {
        events.assertConfined { "PlantState.replace" }
        load(model)
        events.publish(PlantModelReplacedEvent(model))
    }

    private fun lockChanged() {
        snapshot = null
        layout = base.copy(paths = paths.values.toList(), locations = locations.values.toList())
    }

    private fun load(model: PlantModel) {
        base = model
        paths.clear()
        locations.clear()
        vehicles.clear()
        model.paths.associateByTo(paths) { it.name }
        model.locations.associateByTo(locations) { it.name }
        model.vehicles.associateByTo(vehicles) { it.name }
        // Added before stale ones go, so a driver thread never finds its vehicle missing midway.
        published.putAll(vehicles)
        published.keys.retainAll(vehicles.keys)
        snapshot = model
        layout = model
    }
}
