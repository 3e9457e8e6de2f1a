package org.ktcs.kernel.scheduling

import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.scheduling.SchedulerClient

/**
 * Grants decided but not yet announced. Announcing through the clock means a client is never called back from
 * inside its own call to the scheduler.
 */
internal class Deliveries(private val clock: KernelClock) {
    private class Delivery {
        var cancellable: Cancellable? = null
    }

    private val undelivered = HashMap<String, MutableSet<Delivery>>()

    /** Announces [resources] to [client] soon; calls [onRefused] if the client does not want them any more. */
    fun send(client: SchedulerClient, resources: Set<String>, onRefused: () -> Unit) {
        val delivery = Delivery()
        undelivered.getOrPut(client.name, ::HashSet) += delivery
        delivery.cancellable = clock.schedule(0) {
            if (remove(client.name, delivery) && !client.onAllocationGranted(resources)) onRefused()
        }
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
