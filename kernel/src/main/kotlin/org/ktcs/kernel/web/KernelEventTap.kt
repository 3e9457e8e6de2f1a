package org.ktcs.kernel.web

import org.ktcs.api.event.KernelEvent

/**
 * Registers a listener the kernel calls synchronously for every event, in the kernel context (the kernel's
 * `EventBus.listen`). The web API keeps `GET /v1/events`' buffer filled through it: a subscription would wake a
 * thread for every event, which cost more than the buffer's work itself (README, "Performance"). The listener must be
 * quick and must not throw.
 */
fun interface KernelEventTap {
    fun listen(listener: (KernelEvent) -> Unit)
}
