package org.ktcs.kernel.routing

import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.VehicleOrientation
import kotlin.math.roundToLong

private const val COST_FORWARD_PROPERTY = "tcs:routingCostForward"
private const val COST_REVERSE_PROPERTY = "tcs:routingCostReverse"
private const val MILLIS_PER_SECOND = 1000.0

/**
 * The cost of driving a path in one direction for the vehicles of [key]: the sum of the configured evaluators, or
 * `null` when one of them forbids the direction.
 */
internal class EdgeCosts(
    private val model: PlantModel,
    private val configuration: RouterConfiguration,
    private val key: GraphKey,
) {
    private val operationPoints = model.pointsLinkedToLocations()

    fun of(path: Path, orientation: VehicleOrientation): Long? {
        var total = 0L
        for (evaluator in configuration.edgeEvaluators) {
            total += evaluate(evaluator, path, orientation) ?: return null
        }
        val target = if (orientation == VehicleOrientation.BACKWARD) path.sourcePoint else path.destinationPoint
        return if (total > 0 && target in operationPoints) total + surcharge(total) else total
    }

    // Whole percent of a positive cost, rounded down; a route that must end at such a point pays it on every way in.
    private fun surcharge(cost: Long): Long = cost / 100 * configuration.operationPointSurcharge +
        cost % 100 * configuration.operationPointSurcharge / 100

    private fun evaluate(evaluator: EdgeEvaluator, path: Path, orientation: VehicleOrientation): Long? =
        when (evaluator) {
            EdgeEvaluator.DISTANCE -> path.length
            EdgeEvaluator.TRAVELTIME -> travelTime(path, orientation)
            EdgeEvaluator.HOPS -> 1
            EdgeEvaluator.EXPLICIT_PROPERTIES -> explicitCost(path, orientation)
            EdgeEvaluator.BOUNDING_BOX -> boundingBoxCost(path, orientation)
        }

    private fun travelTime(path: Path, orientation: VehicleOrientation): Long? {
        val vehicle = checkNotNull(key.velocities) { "TRAVELTIME needs the vehicle's velocities in the graph key" }
        val velocity = if (orientation == VehicleOrientation.BACKWARD) {
            minOf(vehicle.reverse, path.maxReverseVelocity)
        } else {
            minOf(vehicle.forward, path.maxVelocity)
        }
        return if (velocity <= 0) null else (path.length * MILLIS_PER_SECOND / velocity).roundToLong()
    }

    private fun explicitCost(path: Path, orientation: VehicleOrientation): Long? {
        val prefix = if (orientation == VehicleOrientation.BACKWARD) COST_REVERSE_PROPERTY else COST_FORWARD_PROPERTY
        val value = path.properties[prefix + key.routingGroup.orEmpty()]
        return if (value == null) configuration.explicitPropertiesDefaultValue else parseCost(value)
    }

    private fun boundingBoxCost(path: Path, orientation: VehicleOrientation): Long? {
        val vehicleBox = checkNotNull(key.boundingBox) { "BOUNDING_BOX needs the vehicle's box in the graph key" }
        val target = if (orientation == VehicleOrientation.BACKWARD) path.sourcePoint else path.destinationPoint
        val limit = model.point(target)?.maxVehicleBoundingBox ?: return null
        return if (vehicleBox.protrudesBeyond(limit)) null else 0
    }
}

/** A cost property's value as a whole number; `null` for `Infinity`, `NaN` and anything that is not a number. */
internal fun parseCost(value: String): Long? {
    val text = value.trim()
    return text.toLongOrNull() ?: text.toDoubleOrNull()?.takeIf { it.isFinite() }?.roundToLong()
}
