package org.ktcs.api.order

import java.time.Instant

/**
 * What a client asks for when it creates a transport order.
 *
 * @property name the order's name, or with [incompleteName] a prefix to which the kernel appends a unique suffix
 *   that sorts by creation time.
 * @property destinations where to go and what to do there, in order; at least one.
 * @property dependencies names of orders that must be FINISHED before this one is dispatched.
 */
public data class TransportOrderCreation(
    val name: String,
    val destinations: List<Destination>,
    val incompleteName: Boolean = false,
    val type: String = TransportOrder.DEFAULT_TYPE,
    val deadline: Instant = Instant.MAX,
    val intendedVehicle: String? = null,
    val dependencies: Set<String> = emptySet(),
    val wrappingSequence: String? = null,
    val dispensable: Boolean = false,
    val peripheralReservationToken: String? = null,
    val properties: Map<String, String> = emptyMap(),
)

/**
 * What a client asks for when it creates an order sequence.
 *
 * @property orderTypes the types orders of the sequence may have; `*` allows any.
 */
public data class OrderSequenceCreation(
    val name: String,
    val incompleteName: Boolean = false,
    val type: String = TransportOrder.DEFAULT_TYPE,
    val orderTypes: Set<String> = setOf("*"),
    val intendedVehicle: String? = null,
    val failureFatal: Boolean = false,
    val properties: Map<String, String> = emptyMap(),
)
