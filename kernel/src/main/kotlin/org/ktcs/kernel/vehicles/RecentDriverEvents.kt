package org.ktcs.kernel.vehicles

import org.ktcs.api.event.DriverEvent

/**
 * The latest [DriverEvent]s of each vehicle, at most [perVehicle] each, so a client that connects late (the
 * overview's driver panel, a WebSocket subscriber) sees what happened just before. Confined to the kernel context.
 */
class RecentDriverEvents(private val perVehicle: Int = DEFAULT_PER_VEHICLE) {
    private val byVehicle = HashMap<String, ArrayDeque<DriverEvent>>()

    fun add(event: DriverEvent) {
        val events = byVehicle.getOrPut(event.vehicle) { ArrayDeque() }
        events.addLast(event)
        if (events.size > perVehicle) events.removeFirst()
    }

    /** The events of [vehicle] (`null`: of every vehicle), oldest first. */
    fun of(vehicle: String?): List<DriverEvent> = if (vehicle == null) {
        byVehicle.values.flatten().sortedBy { it.timestamp }
    } else {
        byVehicle[vehicle]?.toList().orEmpty()
    }

    /** Forgets every event, when the plant model is replaced: the old vehicles are gone. */
    fun clear() = byVehicle.clear()

    companion object {
        const val DEFAULT_PER_VEHICLE = 50
    }
}
