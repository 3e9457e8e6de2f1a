package org.ktcs.kernel.orders

import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.workingset.HistoryCodes

/**
 * kTCS's `waitingReason` of an order: the dispatcher's latest reason for not assigning a DISPATCHABLE order. The
 * dispatcher notes each change of reason in the history (openTCS's `orderDispatchingDeferred`), so the latest such
 * entry is the current reason; an order that is no longer DISPATCHABLE waits for nothing.
 */
fun TransportOrder.waitingReason(): String? {
    if (state != TransportOrderState.DISPATCHABLE) return null
    return history.lastOrNull { it.eventCode == HistoryCodes.ORDER_DISPATCHING_DEFERRED }?.supplement?.ifEmpty { null }
}
