package org.ktcs.kernel.web.v1.orders

import kotlinx.serialization.Serializable
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.PropertyDto
import org.ktcs.kernel.web.v1.toDomain

/** The body of `POST /orderSequences/{NAME}`. */
@Serializable
data class PostOrderSequenceRequest(
    val incompleteName: Boolean = false,
    val type: String? = null,
    val orderTypes: List<String>? = null,
    val intendedVehicle: String? = null,
    val failureFatal: Boolean = false,
    val properties: List<PropertyDto>? = null,
)

/** The creation request for a sequence named [name]; absent order types allow any type, as in openTCS. */
fun PostOrderSequenceRequest.toDomain(name: String): OrderSequenceCreation = OrderSequenceCreation(
    name = name,
    incompleteName = incompleteName,
    type = type ?: TransportOrder.DEFAULT_TYPE,
    orderTypes = orderTypes?.toSet() ?: setOf(ANY_TYPE),
    intendedVehicle = intendedVehicle,
    failureFatal = failureFatal,
    properties = properties.orEmpty().toDomain("properties"),
)

private const val ANY_TYPE = "*"
