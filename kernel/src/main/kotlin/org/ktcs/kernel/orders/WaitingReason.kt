package org.ktcs.kernel.orders

import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * kTCS's `waitingReason` of an order: the dispatcher's latest reason for not assigning a DISPATCHABLE order, or the
 * unfinished dependencies of an ACTIVE one. Each change of reason is noted in the history (openTCS's
 * `orderDispatchingDeferred`; `orderDispatchingResumed` once the dependencies are finished), so the latest such entry
 * is the current reason; an order that is neither ACTIVE nor DISPATCHABLE waits for nothing.
 */
fun TransportOrder.waitingReason(): String? {
    if (state != TransportOrderState.DISPATCHABLE && state != TransportOrderState.ACTIVE) return null
    val last = history.lastOrNull {
        it.eventCode == HistoryCodes.ORDER_DISPATCHING_DEFERRED ||
            it.eventCode == HistoryCodes.ORDER_DISPATCHING_RESUMED
    }
    return last?.takeIf { it.eventCode == HistoryCodes.ORDER_DISPATCHING_DEFERRED }?.supplement?.ifEmpty { null }
}
