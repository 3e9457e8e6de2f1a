package org.ktcs.kernel.dispatching

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * Whether a vehicle may take a new order at all (openTCS's `IsAvailableForAnyOrder`). Each filter returns why not, or
 * `null`; a vehicle is available when none objects.
 *
 * A charging vehicle stays unavailable until it is fully recharged if
 * [DispatcherConfiguration.keepRechargingUntilFullyCharged], otherwise until the [DispatchRun.recovery] evaluator says
 * it has recovered; this holds whether it charges idle or while processing a dispensable recharge order.
 */
internal class VehicleAvailability(private val run: DispatchRun) {
    private val filters: List<(Vehicle) -> String?> =
        listOf(::integration, ::position, ::pause, ::charging, ::occupation, ::sequenceBinding)

    fun isAvailable(vehicle: Vehicle): Boolean = filters.all { it(vehicle) == null }

    fun reasons(vehicle: Vehicle): List<String> = filters.mapNotNull { it(vehicle) }

    /** Whether the vehicle has no order and stands idle or charges. */
    fun isIdle(vehicle: Vehicle): Boolean = vehicle.procState == ProcState.IDLE &&
        vehicle.transportOrder == null &&
        (vehicle.state == VehicleState.IDLE || vehicle.state == VehicleState.CHARGING)

    /** The dispensable order the vehicle is processing, which a better order may replace, or `null`. */
    fun dispensableOrder(vehicle: Vehicle): TransportOrder? = vehicle.transportOrder
        ?.let(run::order)
        ?.takeIf { it.dispensable && it.state == TransportOrderState.BEING_PROCESSED }

    private fun integration(vehicle: Vehicle): String? = when (vehicle.integrationLevel) {
        IntegrationLevel.TO_BE_UTILIZED -> null
        else -> "integration level ${vehicle.integrationLevel}"
    }

    private fun position(vehicle: Vehicle): String? = if (vehicle.currentPosition == null) "position unknown" else null

    private fun pause(vehicle: Vehicle): String? = if (vehicle.paused) "paused" else null

    private fun charging(vehicle: Vehicle): String? = when {
        vehicle.state != VehicleState.CHARGING || rechargedEnough(vehicle) -> null

        // No energy level in the text: a reason that changed with every percent would add history entries to every
        // waiting order at each dispatcher run while the vehicle charges.
        else -> "charging"
    }

    private fun rechargedEnough(vehicle: Vehicle): Boolean {
        val thresholds = vehicle.energyLevelThresholdSet
        return if (run.configuration.keepRechargingUntilFullyCharged) {
            vehicle.energyLevel >= thresholds.fullyRecharged
        } else {
            run.recovery.isRecovered(vehicle.energyLevel, thresholds.sufficientlyRecharged, thresholds.fullyRecharged)
        }
    }

    /** Why [vehicle] cannot take another order while it works on one, or `null` if it can. */
    fun occupation(vehicle: Vehicle): String? = when {
        isIdle(vehicle) || dispensableOrder(vehicle) != null -> null
        vehicle.transportOrder != null -> "processing order ${vehicle.transportOrder}"
        else -> "procState ${vehicle.procState}, state ${vehicle.state}"
    }

    /** A sequence binds its vehicle until it is finished, or until the vehicle does its dispensable last order. */
    private fun sequenceBinding(vehicle: Vehicle): String? {
        val name = vehicle.orderSequence ?: return null
        val sequence = run.sequence(name) ?: return null
        val releasing = sequence.complete &&
            vehicle.transportOrder == sequence.orders.lastOrNull() &&
            dispensableOrder(vehicle) != null
        return if (sequence.finished || releasing) null else "bound to order sequence $name"
    }
}
