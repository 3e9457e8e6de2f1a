package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder

/**
 * Why an order that no vehicle was checked against waits: its intended vehicle, or every vehicle, is unavailable
 * (the reasons [VehicleAvailability] gives) or was given another order in this run. Computed at most once per vehicle
 * and run, and the fleet's reason once per run, so a long queue of waiting orders costs one lookup each.
 */
internal class WaitingReasons(
    private val run: DispatchRun,
    private val availability: VehicleAvailability,
    available: List<Vehicle>,
) {
    private val availableNames = available.mapTo(HashSet()) { it.name }
    private val perVehicle = HashMap<String, Refusal>()
    private val fleet: String by lazy {
        run.vehicles.takeIf { it.isNotEmpty() }?.let { vehicles -> describe(vehicles.map(::refusal)) }
            ?: "the plant has no vehicles"
    }

    /** The reason for [order]; `null` only in a plant without vehicles. */
    fun withoutCandidates(order: TransportOrder): String? {
        val intended = order.intendedVehicle ?: return fleet
        val vehicle = run.vehicles.firstOrNull { it.name == intended }
            ?: return "intended vehicle $intended is unknown"
        return "intended vehicle $intended: ${refusal(vehicle).detail}"
    }

    private fun refusal(vehicle: Vehicle): Refusal = perVehicle.getOrPut(vehicle.name) {
        val detail = when {
            run.isAssigned(vehicle) -> "was given another order"
            vehicle.name in availableNames -> "available"
            else -> availability.reasons(vehicle).joinToString(", ")
        }
        Refusal(vehicle.name, detail, "no vehicle is available: $detail")
    }
}
