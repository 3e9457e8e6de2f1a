package org.ktcs.kernel.scheduling

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.scheduling.SchedulerClient

/**
 * Grants decided but not yet announced. Announcing through the clock means a client is never called back from
 * inside its own call to the scheduler.
 */
internal class Deliveries(private val clock: KernelClock) {
    private class Delivery(val resources: Set<String>) {
        var cancellable: Cancellable? = null

        // What the client gave back before hearing of this grant, which includes it: held until the grant is refused.
        val withheld = HashSet<String>()
    }

    private val undelivered = HashMap<String, MutableSet<Delivery>>()

    /**
     * Announces [resources] to [client] soon; calls [onRefused] with what [withhold] kept back for this grant if the
     * client does not want them any more.
     */
    fun send(client: SchedulerClient, resources: Set<String>, onRefused: (Set<String>) -> Unit) {
        val delivery = Delivery(resources)
        undelivered.getOrPut(client.name, ::HashSet) += delivery
        delivery.cancellable = clock.schedule(0) {
            if (remove(client.name, delivery) && !client.onAllocationGranted(resources)) onRefused(delivery.withheld)
        }
    }

    /**
     * Of [released], what [client] must keep holding: a grant it has not heard of yet includes it (a vehicle turning
     * back in a dead end asks again for the point it is leaving; granted at once, it must not be freed meanwhile).
     */
    fun withhold(client: String, released: Set<String>): Set<String> {
        val deliveries = undelivered[client] ?: return emptySet()
        val kept = HashSet<String>()
        for (delivery in deliveries) {
            val mine = released.filterTo(HashSet()) { it in delivery.resources }
            delivery.withheld += mine
            kept += mine
        }
        return kept
    }

    /** Drops the client's unannounced grants, e.g. because it gave everything back meanwhile. */
    fun cancel(client: String) {
        undelivered.remove(client)?.forEach { it.cancellable?.cancel() }
    }

    /** Drops every unannounced grant. */
    fun cancelAll() {
        undelivered.keys.toList().forEach(::cancel)
    }

    private fun remove(client: String, delivery: Delivery): Boolean {
        val deliveries = undelivered[client] ?: return false
        val removed = deliveries.remove(delivery)
        if (deliveries.isEmpty()) undelivered.remove(client)
        return removed
    }
}
