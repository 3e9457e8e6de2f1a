package org.ktcs.kernel.dispatching

import org.ktcs.api.dispatching.Dispatcher

/**
 * A dispatcher that can run on what changed since its previous run: the kernel tells it which orders became
 * dispatchable since then, and that anything else it was told about concerns vehicles. A run must assign exactly what
 * [dispatch] would; it may only skip work whose outcome it knows (the waiting orders no vehicle can take). Anything
 * else that changed (locks, sequences, operators' requests, the periodic safety-net run) makes the kernel call
 * [dispatch] instead.
 */
internal interface IncrementalDispatcher : Dispatcher {
    /** Assigns what can be assigned now; [newOrders] names the orders that became DISPATCHABLE since the last run. */
    fun dispatchChanges(newOrders: Collection<String>)
}
