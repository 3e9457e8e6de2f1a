package org.ktcs.kernel.simulation

import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState

/**
 * For a batch that stalled: one line per vehicle that holds an order and stands, naming where it stands, why its next
 * grant waits ([waitOf]: a [org.ktcs.kernel.scheduling.GrantWait] label) and whom it waits for, with the resources
 * ([waitsFor], the scheduler's wait-for view). What a stall looks like is then in the output, not only that it
 * happened: a knot no rule breaks, or vehicles held back with nobody to wait for.
 */
internal fun stalledVehicleLines(
    vehicles: Collection<Vehicle>,
    waitOf: (String) -> String,
    waitsFor: Map<String, Map<String, Set<String>>>,
): List<String> = vehicles
    .filter { it.transportOrder != null && it.state != VehicleState.EXECUTING }
    .sortedBy { it.name }
    .map { vehicle ->
        val whom = waitsFor[vehicle.name].orEmpty().entries.sortedBy { it.key }
            .joinToString(", ") { (other, resources) -> "$other (${resources.sorted().joinToString(", ")})" }
        val position = vehicle.currentPosition ?: "no position"
        val waits = if (whom.isEmpty()) "" else ", waits for $whom"
        "stalled_vehicle: ${vehicle.name} at $position with ${vehicle.transportOrder}: ${waitOf(vehicle.name)}$waits"
    }
