package org.ktcs.kernel.web.v1.orders

import kotlinx.serialization.Serializable
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step

/** A drive order's route as v1 writes it in transport orders and their SSE events. */
@Serializable
data class RouteDto(val costs: Long, val steps: List<RouteStepDto>)

/**
 * One step of a route. kTCS keeps no per-step costs and does not reroute, so [costs] is 0 and [reroutingType] is
 * `null` (what openTCS writes for a step that was not rerouted).
 */
@Serializable
data class RouteStepDto(
    val path: String?,
    val sourcePoint: String?,
    val destinationPoint: String,
    val vehicleOrientation: String,
    val routeIndex: Int,
    val costs: Long = 0,
    val executionAllowed: Boolean,
    val reroutingType: String? = null,
)

fun Route.toDto(): RouteDto = RouteDto(costs, steps.map { it.toDto() })

fun Step.toDto(): RouteStepDto = RouteStepDto(
    path = path,
    sourcePoint = sourcePoint,
    destinationPoint = destinationPoint,
    vehicleOrientation = vehicleOrientation.name,
    routeIndex = routeIndex,
    executionAllowed = executionAllowed,
)
