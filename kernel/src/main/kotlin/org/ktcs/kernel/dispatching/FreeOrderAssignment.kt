package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * Gives free orders to available vehicles (openTCS's `AssignFreeOrdersPhase`). The scarcer side chooses: with fewer
 * vehicles than orders each vehicle in turn takes its best order, otherwise each order in turn takes its best vehicle.
 * Orders that no vehicle could take get the reasons in their history.
 *
 * [assignNew] is the same phase for a run on changes ([IncrementalDispatcher]): when the previous run left no
 * waiting order that an available vehicle could take and nothing has changed since for the waiting orders, only the
 * new orders are looked at.
 */
internal class FreeOrderAssignment(
    private val run: DispatchRun,
    private val availability: VehicleAvailability,
    private val checks: CandidateChecks,
    private val deferrals: DeferralLog,
    private val passOvers: PassOvers,
) {
    private val eligibility = OrderEligibility(run)
    private val refusals = HashMap<String, MutableList<Refusal>>()
    private val refusalsByVehicle = HashMap<String, MutableSet<String>>()
    private val vehicles: List<Vehicle> by lazy {
        run.vehicles.filter { !run.isAssigned(it) && availability.isAvailable(it) }
    }
    private var reasons: WaitingReasons? = null
    private var carried: WaitingReasons.Given? = null

    fun assign() = assignAll(previous = null, fresh = emptySet())

    /**
     * Does what [assign] would, looking only at what may have changed since the previous run ([previous], from
     * [settled]). While no vehicle can take a waiting order it looks at [newOrders] alone: no vehicle is available, or
     * no new order is free and the waiting orders' reasons still hold; the previous run left none that an available
     * vehicle refused, so an available vehicle that was given none had no order meant for it (which vehicle an order
     * is meant for changes only with a full run), and one that became available since changed the reasons of any
     * order meant for it. Otherwise it assigns as [assign] does, and gives reasons again only to the new orders and
     * those refused in this run if the others' still hold. Returns `false`, having done nothing, if [assign] must run
     * instead (no vehicle is available and the waiting orders' reasons changed).
     */
    fun assignNew(newOrders: Collection<String>, previous: WaitingReasons.Given): Boolean {
        val fresh = newOrders.mapNotNull { name ->
            run.order(name)?.takeIf { it.state == TransportOrderState.DISPATCHABLE && eligibility.isFree(it) }
        }
        if (vehicles.isEmpty() || fresh.isEmpty()) {
            val waiting = waitingReasons()
            if (previous.holdIn(waiting)) {
                recordDeferrals(fresh.filter(::isUnlocked), waiting)
                reportIdleVehicles(::anyWaitingFor)
                carried = previous
                return true
            }
            // Reasons are given after the assignments: they must not come from before them.
            reasons = null
            if (vehicles.isEmpty()) return false
        }
        assignAll(previous, fresh.mapTo(HashSet()) { it.name })
        return true
    }

    /** Assigns; gives reasons to every order left waiting, or only to [fresh] and refused ones if [previous] holds. */
    private fun assignAll(previous: WaitingReasons.Given?, fresh: Set<String>) {
        val orders = run.dispatchableOrders.filter { eligibility.isFree(it) && isUnlocked(it) }
        if (vehicles.isNotEmpty() && orders.isNotEmpty()) {
            if (vehicles.size < orders.size) vehiclesChoose(vehicles, orders) else ordersChoose(orders, vehicles)
        }
        val waiting = waitingReasons()
        if (previous != null && previous.holdIn(waiting)) {
            recordDeferrals(orders.filter { it.name in fresh || it.name in refusals }, waiting)
            carried = previous
        } else {
            recordDeferrals(orders, waiting)
        }
        val left = orders.filter { !run.isAssigned(it) }
        reportIdleVehicles { vehicle -> left.any { it.isFor(vehicle) } }
    }

    /**
     * What this phase leaves for the next run on changes: the reasons the waiting orders have (those given before this
     * run too if it looked only at new orders), or `null` if a vehicle refused an order (the refusals depend on which
     * vehicles were asked, so the next run must ask again) or the kernel refused an assignment.
     */
    fun settled(): WaitingReasons.Given? {
        if (refusals.isNotEmpty() || run.kernelRefused) return null
        val given = waitingReasons().given()
        return carried?.plus(given) ?: given
    }

    private fun waitingReasons(): WaitingReasons =
        reasons ?: WaitingReasons(run, availability, vehicles).also { reasons = it }

    private fun isUnlocked(order: TransportOrder): Boolean {
        val reason = eligibility.lockedTarget(order) ?: return true
        deferrals.record(order.name, reason)
        return false
    }

    private fun anyWaitingFor(vehicle: Vehicle): Boolean = run.dispatchableOrders.any {
        !run.isAssigned(it) && it.isFor(vehicle) && eligibility.isFree(it) && eligibility.lockedTarget(it) == null
    }

    /**
     * Each vehicle in turn takes its best order among its window (the most urgent orders it may take), a due one
     * ([PassOvers]) first.
     */
    private fun vehiclesChoose(vehicles: List<Vehicle>, orders: List<TransportOrder>) {
        val size = run.configuration.orderCandidateWindow
        val ranked = if (size > 0) orders.sortedWith(run.priorities.orders) else orders
        for (vehicle in vehicles.sortedWith(run.priorities.vehicles)) {
            val open = ranked.asSequence().filter { !run.isAssigned(it) && it.isFor(vehicle) }
            val window = (if (size > 0) open.take(size) else open).toList()
            val chosen = bestOf(vehicle, window.filter(passOvers::isDue)) ?: bestOf(vehicle, window) ?: continue
            assign(chosen)
            if (size > 0) passOvers.chose(chosen.order, window)
        }
    }

    private fun bestOf(vehicle: Vehicle, orders: List<TransportOrder>): Candidate? =
        bestCandidate(orders.map { Candidate(vehicle, it) }, run.priorities.orderCandidates, ::assess, ::costsToStart)

    /**
     * A lower bound of the costs of [candidate]'s routes: the cheapest route from the vehicle to any point of its
     * first destination (one search per vehicle and run answers it for every order).
     */
    private fun costsToStart(candidate: Candidate): Long? = costsToFirstDestination(candidate, run.routes::costs)

    private fun ordersChoose(orders: List<TransportOrder>, vehicles: List<Vehicle>) {
        for (order in orders.sortedWith(run.priorities.orders)) {
            val candidates = vehicles.filter { !run.isAssigned(it) && order.isFor(it) }.map { Candidate(it, order) }
            bestCandidate(candidates, run.priorities.vehicleCandidates, ::assess, ::costsFromStart)?.let(::assign)
        }
    }

    /**
     * The same lower bound as [costsToStart] for an order choosing among vehicles: one search backwards from each
     * point of its first destination answers it for every vehicle (of one routing graph).
     */
    private fun costsFromStart(candidate: Candidate): Long? = costsToFirstDestination(candidate, run.routes::costsTo)

    // The cheapest of [costs] from the candidate's vehicle to the points of its order's first destination.
    private fun costsToFirstDestination(candidate: Candidate, costs: (Vehicle, String) -> Long?): Long? {
        val target = candidate.order.driveOrders.firstOrNull()?.destination?.target ?: return null
        val points = run.model.location(target)?.links?.map { it.point } ?: listOf(target)
        return points.mapNotNull { costs(candidate.vehicle, it) }.minOrNull()
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
    private fun reportIdleVehicles(anyWaitingFor: (Vehicle) -> Boolean) {
        for (vehicle in run.vehicles) run.context.vehicleWaiting(vehicle.name, idleReason(vehicle, anyWaitingFor))
    }

    private fun idleReason(vehicle: Vehicle, anyWaitingFor: (Vehicle) -> Boolean): String? {
        if (run.isAssigned(vehicle) || vehicle.transportOrder != null) return null
        if (!anyWaitingFor(vehicle)) return null
        val unavailable = availability.reasons(vehicle)
        if (unavailable.isNotEmpty()) return unavailable.joinToString(", ")
        return refusalsByVehicle[vehicle.name]?.joinToString("; ", prefix = "refuses the waiting orders: ")
    }
}
