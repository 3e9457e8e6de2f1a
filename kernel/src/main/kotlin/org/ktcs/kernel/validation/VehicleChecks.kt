package org.ktcs.kernel.validation

import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Vehicle

private val PERCENT = 0..100

internal fun vehicleProblems(index: ModelIndex): List<ModelProblem> =
    index.model.vehicles.flatMap { vehicleProblems(it, index) }

private fun vehicleProblems(vehicle: Vehicle, index: ModelIndex): List<ModelProblem> =
    thresholdProblems(vehicle, vehicle.energyLevelThresholdSet) +
        listOfNotNull(
            vehicle.negativeVelocity("maxVelocity", vehicle.maxVelocity),
            vehicle.negativeVelocity("maxReverseVelocity", vehicle.maxReverseVelocity),
            unknownEnvelopeKey(vehicle, index),
        ) +
        vehicle.boundingBoxProblems("bounding box", vehicle.boundingBox)

/**
 * openTCS requires every threshold within 0..100, critical <= good and sufficientlyRecharged <= fullyRecharged.
 * It accepts critical > sufficientlyRecharged, so that is only a warning here: such a model still loads there.
 */
private fun thresholdProblems(vehicle: Vehicle, thresholds: EnergyLevelThresholdSet): List<ModelProblem> =
    thresholds.named().mapNotNull { (name, value) ->
        vehicle.errorIf(value !in PERCENT) { "energy level $name must be within $PERCENT, was $value" }
    } + with(thresholds) {
        listOfNotNull(
            vehicle.errorIf(critical > good) { "energy level critical ($critical) must not exceed good ($good)" },
            vehicle.errorIf(sufficientlyRecharged > fullyRecharged) {
                "energy level sufficientlyRecharged ($sufficientlyRecharged) must not exceed " +
                    "fullyRecharged ($fullyRecharged)"
            },
            vehicle.warningIf(critical > sufficientlyRecharged) {
                "energy level critical ($critical) exceeds sufficientlyRecharged ($sufficientlyRecharged): " +
                    "a charging vehicle would count as sufficiently recharged while still critical"
            },
        )
    }

private fun EnergyLevelThresholdSet.named(): List<Pair<String, Int>> = listOf(
    "critical" to critical,
    "good" to good,
    "sufficientlyRecharged" to sufficientlyRecharged,
    "fullyRecharged" to fullyRecharged,
)

private fun unknownEnvelopeKey(vehicle: Vehicle, index: ModelIndex): ModelProblem? = vehicle.envelopeKey?.let { key ->
    vehicle.warningIf(key !in index.envelopeKeys) { "envelope key '$key' is defined by no point or path" }
}
