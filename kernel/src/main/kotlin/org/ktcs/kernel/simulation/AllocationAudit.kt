package org.ktcs.kernel.simulation

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle

/**
 * Counts, after every vehicle event, resources held by two vehicles and points with two vehicles on them. Keeps an
 * index of holders, so each check costs only what the event changed (most vehicle events change no allocation: they
 * cost a comparison).
 */
class AllocationAudit {
    private val holders = HashMap<String, String>()
    private val positions = HashMap<String, String>()

    var doubleAllocations = 0
        private set
    var sharedPositions = 0
        private set

    fun onEvent(event: KernelEvent) {
        if (event !is VehicleEvent) return
        val vehicle = event.current ?: return
        if (event.previous?.allocatedResources != vehicle.allocatedResources) checkAllocations(event.previous, vehicle)
        val previousPosition = event.previous?.currentPosition
        if (previousPosition != vehicle.currentPosition) {
            previousPosition?.let { if (positions[it] == vehicle.name) positions.remove(it) }
            vehicle.currentPosition?.let { point ->
                val other = positions.putIfAbsent(point, vehicle.name)
                if (other != null && other != vehicle.name) sharedPositions++
            }
        }
    }

    private fun checkAllocations(previous: Vehicle?, vehicle: Vehicle) {
        val before = previous?.allocatedResources?.flatten()?.toSet().orEmpty()
        val after = vehicle.allocatedResources.flatten().toSet()
        (before - after).forEach { if (holders[it] == vehicle.name) holders.remove(it) }
        (after - before).forEach { resource ->
            val holder = holders.putIfAbsent(resource, vehicle.name)
            if (holder != null && holder != vehicle.name) doubleAllocations++
        }
    }
}
