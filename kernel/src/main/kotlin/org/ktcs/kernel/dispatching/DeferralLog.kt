package org.ktcs.kernel.dispatching

import org.ktcs.api.dispatching.DispatchContext

/**
 * Tells the kernel why orders wait, but only when the reason changes: a dispatcher runs often, and repeating the same
 * reason every run would bury everything else in the order's history. Lives as long as the dispatcher.
 */
internal class DeferralLog(private val context: DispatchContext) {
    private val lastReasons = HashMap<String, String>()

    fun record(order: String, reason: String) {
        if (lastReasons.put(order, reason) != reason) context.orderWaiting(order, reason)
    }

    fun assigned(order: String) {
        lastReasons.remove(order)
    }

    /** Forgets orders that are no longer dispatchable, so the log does not grow with every order ever seen. */
    fun retainOnly(orders: Set<String>) {
        lastReasons.keys.retainAll(orders)
    }
}
