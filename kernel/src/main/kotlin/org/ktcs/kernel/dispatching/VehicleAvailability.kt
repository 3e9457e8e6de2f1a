package org.ktcs.kernel.dispatching

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * The one answer to "can this vehicle take work now?", with the reasons why not (operators see them as waiting
 * reasons). The dispatcher asks it for free orders, sequence successors and idle vehicles to park or recharge;
 * `assignNow`, the watchdog that moves idle vehicles out of the way and the simulation's dispatcher latency ask it
 * too (openTCS's `IsAvailableForAnyOrder`).
 *
 * A vehicle can take [Work] when it is TO_BE_UTILIZED, its position is known, it is not paused, it has recharged
 * enough if it is charging, and it is free: idle (procState IDLE, no order, state IDLE or CHARGING) or, if the work
 * may replace it, busy only with a dispensable order. A vehicle bound to an order sequence takes only that
 * sequence's orders until the sequence is finished (or it does the sequence's dispensable last order), and a vehicle
 * takes only orders of a type it accepts.
 *
 * [rechargedEnough] is the dispatcher's charging policy (see
 * [DispatcherConfiguration.keepRechargingUntilFullyCharged]); outside the dispatcher nobody holds a charging vehicle
 * back (an operator's `assignNow` is obeyed at once, and an order that moves a vehicle out of the way waits in the
 * dispatcher like any other).
 */
class VehicleAvailability(
    private val order: (String) -> TransportOrder?,
    private val sequence: (String) -> OrderSequence?,
    private val rechargedEnough: (Vehicle) -> Boolean = { true },
) {
    /** Why [vehicle] cannot take [work] now, every reason; empty if it can. */
    fun reasons(vehicle: Vehicle, work: Work = Work()): List<String> = listOfNotNull(
        integration(vehicle),
        position(vehicle),
        pause(vehicle),
        charging(vehicle),
        if (work.mayReplaceDispensable) occupation(vehicle) else idleness(vehicle),
        sequenceBinding(vehicle, work),
        orderType(vehicle, work),
    )

    /** Whether [vehicle] can take [work] now. */
    fun isAvailable(vehicle: Vehicle, work: Work = Work()): Boolean = reasons(vehicle, work).isEmpty()

    /** Whether the vehicle has no order and stands idle or charges. */
    fun isIdle(vehicle: Vehicle): Boolean = vehicle.procState == ProcState.IDLE &&
        vehicle.transportOrder == null &&
        (vehicle.state == VehicleState.IDLE || vehicle.state == VehicleState.CHARGING)

    /** The dispensable order the vehicle is processing, which a better order may replace, or `null`. */
    fun dispensableOrder(vehicle: Vehicle): TransportOrder? = vehicle.transportOrder
        ?.let(order)
        ?.takeIf { it.dispensable && it.state == TransportOrderState.BEING_PROCESSED }

    /** Why [vehicle] cannot take another order while it works on one, or `null` if it can. */
    fun occupation(vehicle: Vehicle): String? = if (dispensableOrder(vehicle) != null) null else idleness(vehicle)

    private fun idleness(vehicle: Vehicle): String? = when {
        isIdle(vehicle) -> null
        vehicle.transportOrder != null -> "processing order ${vehicle.transportOrder}"
        else -> "procState ${vehicle.procState}, state ${vehicle.state}"
    }

    private fun integration(vehicle: Vehicle): String? = when (vehicle.integrationLevel) {
        IntegrationLevel.TO_BE_UTILIZED -> null
        else -> "integration level ${vehicle.integrationLevel}"
    }

    private fun position(vehicle: Vehicle): String? = if (vehicle.currentPosition == null) "position unknown" else null

    private fun pause(vehicle: Vehicle): String? = if (vehicle.paused) "paused" else null

    // No energy level in the text: a reason that changed with every percent would add history entries to every
    // waiting order at each dispatcher run while the vehicle charges.
    private fun charging(vehicle: Vehicle): String? =
        if (vehicle.state == VehicleState.CHARGING && !rechargedEnough(vehicle)) "charging" else null

    private fun sequenceBinding(vehicle: Vehicle, work: Work): String? {
        val name = vehicle.orderSequence ?: return null
        if (name == work.sequence) return null
        val bound = sequence(name) ?: return null
        val releasing = bound.complete &&
            vehicle.transportOrder == bound.orders.lastOrNull() &&
            dispensableOrder(vehicle) != null
        return if (bound.finished || releasing) null else "bound to order sequence $name"
    }

    private fun orderType(vehicle: Vehicle, work: Work): String? {
        val type = work.orderType ?: return null
        return if (vehicle.accepts(type)) null else "does not accept type '$type'"
    }

    /**
     * What a vehicle is asked to take: an order of [orderType] (`null`: any type) that belongs to [sequence] (`null`:
     * none), which may or may not replace a dispensable order the vehicle is processing.
     */
    data class Work(
        val orderType: String? = null,
        val sequence: String? = null,
        val mayReplaceDispensable: Boolean = true,
    )

    companion object {
        /** The dispatcher's view: its run's lookups and its charging policy. */
        internal fun of(run: DispatchRun) = VehicleAvailability(run::order, run::sequence) { vehicle ->
            val thresholds = vehicle.energyLevelThresholdSet
            if (run.configuration.keepRechargingUntilFullyCharged) {
                vehicle.energyLevel >= thresholds.fullyRecharged
            } else {
                run.recovery.isRecovered(
                    vehicle.energyLevel,
                    thresholds.sufficientlyRecharged,
                    thresholds.fullyRecharged,
                )
            }
        }
    }
}
