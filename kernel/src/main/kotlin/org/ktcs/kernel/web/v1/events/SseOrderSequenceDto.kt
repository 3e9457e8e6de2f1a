package org.ktcs.kernel.web.v1.events

import kotlinx.serialization.Serializable
import org.ktcs.api.order.OrderSequence
import org.ktcs.kernel.web.v1.ObjectHistoryDto
import org.ktcs.kernel.web.v1.orders.orMaxInstant
import org.ktcs.kernel.web.v1.toDto
import org.ktcs.kernel.web.v1.toWire

/** An order sequence in an SSE event; properties are a JSON object here. */
@Serializable
data class SseOrderSequenceDto(
    val name: String,
    val properties: Map<String, String>,
    val history: ObjectHistoryDto,
    val type: String,
    val orderTypes: List<String>,
    val orders: List<String>,
    val finishedIndex: Int,
    val complete: Boolean,
    val finished: Boolean,
    val failureFatal: Boolean,
    val intendedVehicle: String?,
    val processingVehicle: String?,
    val creationTime: String,
    val finishedTime: String,
)

fun OrderSequence.toSseDto(): SseOrderSequenceDto = SseOrderSequenceDto(
    name = name,
    properties = properties,
    history = history.toDto(),
    type = type,
    orderTypes = orderTypes.toList(),
    orders = orders,
    finishedIndex = finishedIndex,
    complete = complete,
    finished = finished,
    failureFatal = failureFatal,
    intendedVehicle = intendedVehicle,
    processingVehicle = processingVehicle,
    creationTime = creationTime.toWire(),
    finishedTime = finishedTime.orMaxInstant(),
)
