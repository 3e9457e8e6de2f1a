package org.ktcs.kernel.orders

/** History event codes, with openTCS's names so clients recognise them. */
object HistoryCodes {
    const val ORDER_CREATED = "tcs:history:orderCreated"
    const val ORDER_ASSIGNED = "tcs:history:orderAssignedToVehicle"
    const val ORDER_DISPATCHING_DEFERRED = "tcs:history:orderDispatchingDeferred"
    const val ORDER_DISPATCHING_RESUMED = "tcs:history:orderDispatchingResumed"
    const val ORDER_FINISHED_DRIVE_ORDER = "tcs:history:orderFinishedDriveOrder"
    const val ORDER_REACHED_FINAL_STATE = "tcs:history:orderReachedFinalState"
    const val SEQUENCE_CREATED = "tcs:history:sequenceCreated"
    const val SEQUENCE_ORDER_APPENDED = "tcs:history:sequenceOrderAppended"
    const val SEQUENCE_COMPLETED = "tcs:history:sequenceCompleted"
    const val SEQUENCE_FINISHED = "tcs:history:sequenceFinished"
}
