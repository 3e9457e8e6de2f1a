package org.ktcs.api.order

/**
 * The life cycle of a transport order, with openTCS's names:
 * RAW → ACTIVE → DISPATCHABLE → BEING_PROCESSED → FINISHED, with UNROUTABLE, WITHDRAWN and FAILED on the way.
 */
public enum class TransportOrderState {
    /** Created, not yet checked. */
    RAW,

    /** Checked and routable, waiting for its dependencies. */
    ACTIVE,

    /** Ready to be assigned to a vehicle. */
    DISPATCHABLE,

    /** Assigned to a vehicle that is working on it. */
    BEING_PROCESSED,

    /** Withdrawn; the vehicle stops working on it and the order will fail. */
    WITHDRAWN,

    /** Done: every drive order was carried out. */
    FINISHED,

    /** Given up on, after a withdrawal or a failed dependency. */
    FAILED,

    /** No vehicle can reach its destinations. */
    UNROUTABLE,
    ;

    /** Whether the order can never change state again. */
    public val isFinal: Boolean get() = this == FINISHED || this == FAILED || this == UNROUTABLE
}

/** The life cycle of one drive order (one destination of a transport order). */
public enum class DriveOrderState {
    PRISTINE,
    TRAVELLING,
    OPERATING,
    FINISHED,
    FAILED,
}
