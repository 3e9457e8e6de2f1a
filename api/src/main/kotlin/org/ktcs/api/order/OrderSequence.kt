package org.ktcs.api.order

import java.time.Instant

/**
 * Transport orders that one vehicle processes one after the other, without taking other orders in between.
 *
 * @property orders names of the sequence's orders, in the order they are processed.
 * @property orderTypes the types the sequence's orders may have.
 * @property finishedIndex index of the last finished order, -1 before the first.
 * @property complete no orders will be added any more.
 * @property finished complete and every order is final.
 * @property failureFatal when one order fails, all following ones fail too.
 */
public data class OrderSequence(
    val name: String,
    val creationTime: Instant,
    val type: String = TransportOrder.DEFAULT_TYPE,
    val orderTypes: Set<String> = setOf("*"),
    val orders: List<String> = emptyList(),
    val finishedIndex: Int = -1,
    val complete: Boolean = false,
    val finished: Boolean = false,
    val finishedTime: Instant? = null,
    val failureFatal: Boolean = false,
    val intendedVehicle: String? = null,
    val processingVehicle: String? = null,
    val properties: Map<String, String> = emptyMap(),
    val history: List<HistoryEntry> = emptyList(),
)
