package org.ktcs.kernel.web.v1.vehicles

import kotlinx.serialization.Serializable
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.kernel.web.v1.required

/** The body of `POST /vehicles/{NAME}/routeComputationQuery`. */
@Serializable
data class PostRouteComputationRequest(
    val destinationPoints: List<String>? = null,
    val sourcePoint: String? = null,
    val resourcesToAvoid: List<String>? = null,
)

/** What a route computation asks for; [sourcePoint] `null` means where the vehicle is. */
data class RouteComputationQuery(
    val sourcePoint: String?,
    val destinationPoints: List<String>,
    val resourcesToAvoid: Set<String>,
)

fun PostRouteComputationRequest.toDomain(): RouteComputationQuery {
    val destinations = destinationPoints.required("destinationPoints")
    if (destinations.isEmpty()) throw InvalidRequestException("destinationPoints must not be empty")
    return RouteComputationQuery(sourcePoint, destinations, resourcesToAvoid.orEmpty().toSet())
}

/** The answer of a route computation query: the routes found per destination point. */
@Serializable
data class RouteComputationResponse(val routes: List<ComputedRouteDto>)

/** A route to [destinationPoint]; without a route, [costs] is -1 and [steps] `null`, as openTCS writes it. */
@Serializable
data class ComputedRouteDto(val destinationPoint: String, val costs: Long, val steps: List<ComputedStepDto>?)

@Serializable
data class ComputedStepDto(
    val path: String?,
    val sourcePoint: String?,
    val destinationPoint: String,
    val vehicleOrientation: String,
)

/** The routes per destination, in the query's order of destination points. */
fun Map<String, List<Route>>.toRouteComputationResponse(): RouteComputationResponse =
    RouteComputationResponse(entries.flatMap { (destination, routes) -> routes.toDtos(destination) })

private fun List<Route>.toDtos(destination: String): List<ComputedRouteDto> =
    if (isEmpty()) {
        listOf(ComputedRouteDto(destination, NO_ROUTE_COSTS, null))
    } else {
        map { route -> ComputedRouteDto(destination, route.costs, route.steps.map { it.toComputedStep() }) }
    }

private fun Step.toComputedStep() = ComputedStepDto(path, sourcePoint, destinationPoint, vehicleOrientation.name)

private const val NO_ROUTE_COSTS = -1L
