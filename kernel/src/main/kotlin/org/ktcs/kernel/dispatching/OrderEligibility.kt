package org.ktcs.kernel.dispatching

import org.ktcs.api.order.TransportOrder

/** Which dispatchable orders may go to any free vehicle (openTCS's order selection filters). */
internal class OrderEligibility(private val run: DispatchRun) {
    /**
     * Whether the order may be given to a free vehicle now, with no reason worth recording if not: it was assigned in
     * this run already, its sequence has a vehicle (which gets it as its successor), or an earlier order of its
     * sequence is not done yet.
     */
    fun isFree(order: TransportOrder): Boolean {
        if (run.isAssigned(order)) return false
        val name = order.wrappingSequence ?: return true
        val sequence = run.sequence(name) ?: return true
        if (sequence.processingVehicle != null) return false
        val next = sequence.orders.drop(sequence.finishedIndex + 1).firstOrNull {
            run.order(it)?.state?.isFinal == false
        }
        return next == order.name
    }

    /** Why the order cannot go anywhere now: a location it goes to is locked; `null` if none is. */
    fun lockedTarget(order: TransportOrder): String? {
        if (lockedLocations.isEmpty()) return null
        return order.driveOrders
            .map { it.destination.target }
            .firstOrNull { it in lockedLocations }
            ?.let { "target location $it is locked" }
    }

    // Asked for every waiting order in every run; locations are rarely locked, so most runs skip the lookups.
    private val lockedLocations: Set<String> by lazy {
        run.model.locations.filter { it.locked }.mapTo(HashSet()) { it.name }
    }
}
