package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder

/**
 * Why an order that no vehicle was checked against waits: its intended vehicle, or every vehicle, is unavailable
 * (the reasons [VehicleAvailability] gives) or was given another order in this run. Computed at most once per vehicle
 * and run, and the fleet's reason once per run, so a long queue of waiting orders costs one lookup each.
 *
 * The fleet's reason names busy vehicles but not their orders: it is the same for every order waiting without an
 * intended vehicle, so a reason that changed with every assignment would add a history entry to each of them every
 * time a vehicle takes its next order (thousands of entries per order in a long queue). A vehicle's own order is in
 * its details, and an order's intended vehicle is named with its order.
 */
internal class WaitingReasons(
    private val run: DispatchRun,
    private val availability: VehicleAvailability,
    available: List<Vehicle>,
) {
    private val availableNames = available.mapTo(HashSet()) { it.name }
    private val perVehicle = HashMap<String, Refusal>()
    private val fleet: String by lazy {
        run.vehicles.takeIf { it.isNotEmpty() }?.let(::describeFleet) ?: "the plant has no vehicles"
    }

    private val given = HashMap<String?, String>()

    /** The reason for [order]; `null` only in a plant without vehicles. */
    fun withoutCandidates(order: TransportOrder): String? {
        val intended = order.intendedVehicle
        return reasonFor(intended).also { given[intended] = it }
    }

    /** The reasons [withoutCandidates] gave so far. */
    fun given(): Given = Given(HashMap(given))

    private fun reasonFor(intended: String?): String {
        if (intended == null) return fleet
        val vehicle = run.vehicles.firstOrNull { it.name == intended } ?: return "intended vehicle $intended is unknown"
        return "intended vehicle $intended: ${refusal(vehicle).detail}"
    }

    /**
     * Reasons given to waiting orders, by their intended vehicle (`null`: none). While they [holdIn] a later run, that
     * run gives each of those orders the reason it has.
     */
    class Given(private val reasons: Map<String?, String>) {
        fun holdIn(
            later: WaitingReasons,
        ): Boolean = reasons.all { (intended, text) -> later.reasonFor(intended) == text }

        operator fun plus(later: Given): Given = Given(reasons + later.reasons)
    }

    private fun describeFleet(vehicles: List<Vehicle>): String {
        // Split in one pass: asking a list of busy vehicles whether it holds each vehicle compared whole vehicles,
        // fleet times fleet, at every dispatcher run.
        val (busy, free) = vehicles.partition(::isBusy)
        if (free.isEmpty()) return "every vehicle is busy with an order: ${names(busy)}"
        val others = free.map(::refusal)
        val busyPart = if (busy.isEmpty()) emptyList() else listOf("busy with an order: ${names(busy)}")
        return (busyPart + describe(others)).joinToString("; ")
    }

    // A vehicle given an order in this run is as busy as one given an order before it: naming the difference would
    // change every waiting order's reason twice per assignment.
    private fun isBusy(vehicle: Vehicle): Boolean = run.isAssigned(vehicle) || isOnlyOccupied(vehicle)

    private fun isOnlyOccupied(vehicle: Vehicle): Boolean = vehicle.name !in availableNames &&
        vehicle.transportOrder != null &&
        availability.reasons(vehicle).singleOrNull() == availability.occupation(vehicle)

    private fun names(vehicles: List<Vehicle>): String {
        val sorted = vehicles.map { it.name }.sorted()
        val shown = sorted.take(MAX_NAMED).joinToString(", ")
        return if (sorted.size > MAX_NAMED) "$shown and ${sorted.size - MAX_NAMED} more" else shown
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

private const val MAX_NAMED = 4
