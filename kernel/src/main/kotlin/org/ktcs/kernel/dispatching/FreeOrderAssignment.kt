package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder

/**
 * Gives free orders to available vehicles (openTCS's `AssignFreeOrdersPhase`). The scarcer side chooses: with fewer
 * vehicles than orders each vehicle in turn takes its best order, otherwise each order in turn takes its best vehicle.
 * Orders that no vehicle could take get the reasons in their history.
 */
internal class FreeOrderAssignment(
    private val run: DispatchRun,
    private val availability: VehicleAvailability,
    private val checks: CandidateChecks,
    private val deferrals: DeferralLog,
) {
    private val eligibility = OrderEligibility(run)
    private val refusals = HashMap<String, MutableList<Refusal>>()
    private val refusalsByVehicle = HashMap<String, MutableSet<String>>()

    fun assign() {
        val vehicles = run.vehicles.filter { !run.isAssigned(it) && availability.isAvailable(it) }
        val orders = run.dispatchableOrders.filter { eligibility.isFree(it) && isUnlocked(it) }
        if (vehicles.isNotEmpty() && orders.isNotEmpty()) {
            if (vehicles.size < orders.size) vehiclesChoose(vehicles, orders) else ordersChoose(orders, vehicles)
        }
        recordDeferrals(orders, WaitingReasons(run, availability, vehicles))
        reportIdleVehicles(orders)
    }

    private fun isUnlocked(order: TransportOrder): Boolean {
        val reason = eligibility.lockedTarget(order) ?: return true
        deferrals.record(order.name, reason)
        return false
    }

    private fun vehiclesChoose(vehicles: List<Vehicle>, orders: List<TransportOrder>) {
        for (vehicle in vehicles.sortedWith(run.priorities.vehicles)) {
            val candidates = orders.filter { !run.isAssigned(it) && it.isFor(vehicle) }.map { Candidate(vehicle, it) }
            bestCandidate(candidates, run.priorities.orderCandidates, ::assess)?.let(::assign)
        }
    }

    private fun ordersChoose(orders: List<TransportOrder>, vehicles: List<Vehicle>) {
        for (order in orders.sortedWith(run.priorities.orders)) {
            val candidates = vehicles.filter { !run.isAssigned(it) && order.isFor(it) }.map { Candidate(it, order) }
            bestCandidate(candidates, run.priorities.vehicleCandidates, ::assess)?.let(::assign)
        }
    }

    private fun TransportOrder.isFor(vehicle: Vehicle): Boolean =
        intendedVehicle == null || intendedVehicle == vehicle.name

    private fun assess(candidate: Candidate): Candidate? = when (val assessment = checks.forFreeOrder(candidate)) {
        is Assessment.Accepted -> assessment.candidate

        is Assessment.Refused -> {
            refusals.getOrPut(candidate.order.name) { mutableListOf() } += assessment.refusal
            refusalsByVehicle.getOrPut(candidate.vehicle.name) { LinkedHashSet() } += assessment.refusal.detail
            null
        }
    }

    private fun assign(candidate: Candidate) {
        if (run.assign(candidate)) deferrals.assigned(candidate.order.name)
    }

    /** Every order left waiting gets a reason: the vehicles' refusals, else why no vehicle could be asked. */
    private fun recordDeferrals(orders: List<TransportOrder>, waiting: WaitingReasons) {
        orders.filter { !run.isAssigned(it) }.forEach { order ->
            val reason = refusals[order.name]?.let(::describe) ?: waiting.withoutCandidates(order) ?: return@forEach
            deferrals.record(order.name, reason)
        }
    }

    /** Tells why each idle vehicle took none of the orders left waiting: it is unavailable, or it refused them. */
    private fun reportIdleVehicles(orders: List<TransportOrder>) {
        val waiting = orders.filter { !run.isAssigned(it) }
        for (vehicle in run.vehicles) run.context.vehicleWaiting(vehicle.name, idleReason(vehicle, waiting))
    }

    private fun idleReason(vehicle: Vehicle, waiting: List<TransportOrder>): String? {
        if (run.isAssigned(vehicle) || vehicle.transportOrder != null) return null
        if (waiting.none { it.isFor(vehicle) }) return null
        val unavailable = availability.reasons(vehicle)
        if (unavailable.isNotEmpty()) return unavailable.joinToString(", ")
        return refusalsByVehicle[vehicle.name]?.joinToString("; ", prefix = "refuses the waiting orders: ")
    }
}
