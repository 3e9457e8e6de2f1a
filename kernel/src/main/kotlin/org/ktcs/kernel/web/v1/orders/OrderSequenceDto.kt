package org.ktcs.kernel.web.v1.orders

import kotlinx.serialization.Serializable
import org.ktcs.api.order.OrderSequence
import org.ktcs.kernel.web.v1.PropertyDto
import org.ktcs.kernel.web.v1.toPropertyDtos
import org.ktcs.kernel.web.v1.toWire

/** An order sequence as `GET /orderSequences/{NAME}` answers it. */
@Serializable
data class OrderSequenceDto(
    val name: String,
    val type: String,
    val orderTypes: List<String>,
    val orders: List<String>,
    val finishedIndex: Int,
    val complete: Boolean,
    val finished: Boolean,
    val failureFatal: Boolean,
    val creationTime: String,
    val finishedTime: String,
    val intendedVehicle: String?,
    val processingVehicle: String?,
    val properties: List<PropertyDto>,
)

fun OrderSequence.toDto(): OrderSequenceDto = OrderSequenceDto(
    name = name,
    type = type,
    orderTypes = orderTypes.toList(),
    orders = orders,
    finishedIndex = finishedIndex,
    complete = complete,
    finished = finished,
    failureFatal = failureFatal,
    creationTime = creationTime.toWire(),
    finishedTime = finishedTime.orMaxInstant(),
    intendedVehicle = intendedVehicle,
    processingVehicle = processingVehicle,
    properties = properties.toPropertyDtos(),
)
