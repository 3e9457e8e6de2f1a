package org.ktcs.kernel.web.ws

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle

/**
 * Events that wait together for a WebSocket client, as they go out. A vehicle arriving at a point reports its point,
 * its pose and the resources it released in one kernel step: three events a client would only apply one after the
 * other. A vehicle's change that only moved it (its resources, state, proc state and order stay as they were) is
 * therefore merged with the vehicle's next change when no other vehicle changed in between: one event from the state
 * before the first to the state after the second. Every allocation, state and order change still reaches the client
 * as its own event, and vehicles' events keep the kernel's order.
 */
internal object WsBatch {
    fun coalesce(events: List<KernelEvent>): List<KernelEvent> {
        val out = ArrayList<KernelEvent>(events.size)
        var lastVehicleEvent = -1
        for (event in events) {
            if (event !is VehicleEvent) {
                out += event
                continue
            }
            val before = out.getOrNull(lastVehicleEvent) as VehicleEvent?
            if (before != null && mayMerge(before, event)) {
                out[lastVehicleEvent] = VehicleEvent(before.previous, event.current)
            } else {
                out += event
                lastVehicleEvent = out.lastIndex
            }
        }
        return out
    }

    private fun mayMerge(first: VehicleEvent, next: VehicleEvent): Boolean {
        val (previous, current) = (first.previous ?: return false) to (first.current ?: return false)
        return current === next.previous && next.current != null && onlyMoved(previous, current)
    }

    private fun onlyMoved(before: Vehicle, after: Vehicle) =
        before.allocatedResources == after.allocatedResources &&
            before.claimedResources == after.claimedResources &&
            before.state == after.state &&
            before.procState == after.procState &&
            before.transportOrder == after.transportOrder &&
            before.integrationLevel == after.integrationLevel &&
            before.paused == after.paused
}
