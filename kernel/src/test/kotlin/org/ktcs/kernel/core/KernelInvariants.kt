package org.ktcs.kernel.core

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.VehicleEvent

/**
 * Checks after every vehicle event that no resource is held by two vehicles and no two vehicles stand on one
 * point, keeping an index so each check costs only what changed.
 */
class KernelInvariants {
    private val holders = HashMap<String, String>()
    private val positions = HashMap<String, String>()
    val violations = mutableListOf<String>()

    fun onEvent(event: KernelEvent) {
        if (event !is VehicleEvent) return
        val vehicle = event.current ?: return
        val before = event.previous?.allocatedResources?.flatten()?.toSet().orEmpty()
        val after = vehicle.allocatedResources.flatten().toSet()
        (before - after).forEach { if (holders[it] == vehicle.name) holders.remove(it) }
        (after - before).forEach { resource ->
            val holder = holders.putIfAbsent(resource, vehicle.name)
            if (holder != null && holder != vehicle.name) violations += "$resource held by $holder and ${vehicle.name}"
        }
        event.previous?.currentPosition?.let { if (positions[it] == vehicle.name) positions.remove(it) }
        vehicle.currentPosition?.let { point ->
            val other = positions.putIfAbsent(point, vehicle.name)
            if (other != null && other != vehicle.name) violations += "${vehicle.name} and $other both on $point"
        }
    }
}
