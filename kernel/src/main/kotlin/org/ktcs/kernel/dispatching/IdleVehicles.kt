package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

/**
 * Vehicles that may be sent to recharge or park (openTCS's `IsIdleAndDegraded` and `IsParkable` without the energy
 * and position parts): available, idle with state IDLE for long enough, without order or sequence, not yet given an
 * order in this run, and without a dispensable order waiting for them (which would be a park or recharge order that
 * could not be assigned, so another one would pile up next to it).
 */
internal class IdleVehicles(private val run: DispatchRun, private val availability: VehicleAvailability) {
    private val awaitedByDispensable: Set<String> by lazy {
        run.dispatchableOrders.filter { it.dispensable }.mapNotNullTo(HashSet()) { it.intendedVehicle }
    }

    /** The vehicles idle for at least [delayMillis] that accept orders of [type], by name. */
    fun select(delayMillis: Long, type: String): List<Vehicle> = run.vehicles
        .filter { isIdle(it) && run.idleMillis(it) >= delayMillis && it.accepts(type) }
        .sortedBy { it.name }

    // Charging vehicles are left alone: they are where they should be.
    // The waiting orders are read last: a run in which no vehicle is idle and available never reads them.
    private fun isIdle(vehicle: Vehicle): Boolean = vehicle.state == VehicleState.IDLE &&
        vehicle.orderSequence == null &&
        !run.isAssigned(vehicle) &&
        availability.isAvailable(vehicle, VehicleAvailability.Work(mayReplaceDispensable = false)) &&
        vehicle.name !in awaitedByDispensable
}
