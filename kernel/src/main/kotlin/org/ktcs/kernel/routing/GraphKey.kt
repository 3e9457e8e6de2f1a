package org.ktcs.kernel.routing

import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Vehicle

/** The vehicle property naming the vehicle's routing group; vehicles without it are in the group "". */
internal const val ROUTING_GROUP_PROPERTY = "tcs:routingGroup"

/**
 * What a routing graph depends on besides the plant model. Vehicles with equal keys share one graph, so a field is
 * set only when a configured cost function reads it; otherwise it is `null` and does not split the vehicles.
 *
 * @property routingGroup read by [EdgeEvaluator.EXPLICIT_PROPERTIES].
 * @property velocities read by [EdgeEvaluator.TRAVELTIME].
 * @property boundingBox read by [EdgeEvaluator.BOUNDING_BOX].
 */
internal data class GraphKey(val routingGroup: String?, val velocities: Velocities?, val boundingBox: BoundingBox?)

/** A vehicle's maximum velocities in mm/s. */
internal data class Velocities(val forward: Int, val reverse: Int)

internal fun RouterConfiguration.graphKeyOf(vehicle: Vehicle): GraphKey = GraphKey(
    routingGroup = vehicle.routingGroup.takeIf { EdgeEvaluator.EXPLICIT_PROPERTIES in edgeEvaluators },
    velocities = Velocities(vehicle.maxVelocity, vehicle.maxReverseVelocity)
        .takeIf { EdgeEvaluator.TRAVELTIME in edgeEvaluators },
    boundingBox = vehicle.boundingBox.takeIf { EdgeEvaluator.BOUNDING_BOX in edgeEvaluators },
)

internal val Vehicle.routingGroup: String get() = properties[ROUTING_GROUP_PROPERTY].orEmpty()
