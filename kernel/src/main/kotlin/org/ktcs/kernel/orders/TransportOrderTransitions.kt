package org.ktcs.kernel.orders

import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.order.TransportOrderState.ACTIVE
import org.ktcs.api.order.TransportOrderState.BEING_PROCESSED
import org.ktcs.api.order.TransportOrderState.DISPATCHABLE
import org.ktcs.api.order.TransportOrderState.FAILED
import org.ktcs.api.order.TransportOrderState.FINISHED
import org.ktcs.api.order.TransportOrderState.RAW
import org.ktcs.api.order.TransportOrderState.UNROUTABLE
import org.ktcs.api.order.TransportOrderState.WITHDRAWN

/**
 * The transport-order life cycle: every allowed state change, in one table (openTCS's state diagram). Any other
 * change is refused by [TransportOrderPool.transition].
 */
object TransportOrderTransitions {
    private val successors = TransportOrderState.entries.associateWith { state ->
        when (state) {
            RAW -> setOf(ACTIVE, UNROUTABLE, WITHDRAWN)
            ACTIVE -> setOf(DISPATCHABLE, UNROUTABLE, WITHDRAWN)
            DISPATCHABLE -> setOf(BEING_PROCESSED, WITHDRAWN)
            BEING_PROCESSED -> setOf(FINISHED, WITHDRAWN, FAILED)
            WITHDRAWN -> setOf(FAILED)
            FINISHED, FAILED, UNROUTABLE -> emptySet()
        }
    }

    /** Whether an order may go from [from] to [to]. */
    fun isAllowed(from: TransportOrderState, to: TransportOrderState): Boolean = to in successors.getValue(from)

    /** The states an order in [state] may go to. */
    fun successorsOf(state: TransportOrderState): Set<TransportOrderState> = successors.getValue(state)
}
