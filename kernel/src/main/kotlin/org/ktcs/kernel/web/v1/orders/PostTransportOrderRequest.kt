package org.ktcs.kernel.web.v1.orders

import kotlinx.serialization.Serializable
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.web.v1.PropertyDto
import org.ktcs.kernel.web.v1.parseInstant
import org.ktcs.kernel.web.v1.required
import org.ktcs.kernel.web.v1.toDomain
import java.time.Instant

/**
 * The body of `POST /transportOrders/{NAME}`. Every field may be absent in the JSON so that [toDomain] can name the
 * missing one instead of failing inside the decoder.
 */
@Serializable
data class PostTransportOrderRequest(
    val incompleteName: Boolean = false,
    val dispensable: Boolean = false,
    val deadline: String? = null,
    val intendedVehicle: String? = null,
    val peripheralReservationToken: String? = null,
    val wrappingSequence: String? = null,
    val type: String? = null,
    val destinations: List<DestinationRequestDto>? = null,
    val properties: List<PropertyDto>? = null,
    val dependencies: List<String>? = null,
)

@Serializable
data class DestinationRequestDto(
    val locationName: String? = null,
    val operation: String? = null,
    val properties: List<PropertyDto>? = null,
)

/** The creation request for an order named [name] (a prefix if [PostTransportOrderRequest.incompleteName]). */
fun PostTransportOrderRequest.toDomain(name: String): TransportOrderCreation = TransportOrderCreation(
    name = name,
    destinations = destinationsToDomain(),
    incompleteName = incompleteName,
    type = type ?: TransportOrder.DEFAULT_TYPE,
    deadline = deadline?.let { parseInstant(it, "deadline") } ?: Instant.MAX,
    intendedVehicle = intendedVehicle,
    dependencies = dependencies.orEmpty().toSet(),
    wrappingSequence = wrappingSequence,
    dispensable = dispensable,
    peripheralReservationToken = peripheralReservationToken,
    properties = properties.orEmpty().toDomain("properties"),
)

private fun PostTransportOrderRequest.destinationsToDomain(): List<Destination> {
    val destinations = destinations.required("destinations")
    if (destinations.isEmpty()) throw InvalidRequestException("destinations must not be empty")
    return destinations.mapIndexed { i, destination -> destination.toDomain("destinations[$i]") }
}

private fun DestinationRequestDto.toDomain(field: String) = Destination(
    target = locationName.required("$field.locationName"),
    operation = operation.required("$field.operation"),
    properties = properties.orEmpty().toDomain("$field.properties"),
)
