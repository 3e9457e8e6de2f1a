package org.ktcs.kernel.events

import kotlinx.coroutines.channels.ReceiveChannel
import org.ktcs.api.event.KernelEvent

/** The kernel's events to listen to or subscribe to; only the kernel's core publishes ([EventBus]). */
interface KernelEvents {
    /** Calls [listener] for every event, in the kernel context, before the event reaches subscribers. */
    fun listen(listener: (KernelEvent) -> Unit)

    /** A new subscription that receives every event published from now on, buffering up to [capacity]. */
    fun subscribe(capacity: Int = EventBus.DEFAULT_CAPACITY): ReceiveChannel<KernelEvent>

    /** How many subscriptions are open now. */
    val subscriberCount: Int
}
