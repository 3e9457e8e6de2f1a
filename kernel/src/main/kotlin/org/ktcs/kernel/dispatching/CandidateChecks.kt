package org.ktcs.kernel.dispatching

import org.ktcs.api.order.Operations
import org.ktcs.kernel.routing.lockedPathsOnWay

/** The outcome of checking whether a vehicle can do an order. */
internal sealed interface Assessment {
    /** It can, with the routes in [candidate]. */
    data class Accepted(val candidate: Candidate) : Assessment

    /** It cannot, because of [refusal]. */
    data class Refused(val refusal: Refusal) : Assessment
}

/** A check of one vehicle against one order: why the vehicle cannot do it, or `null`. */
internal typealias CandidateFilter = (Candidate) -> Refusal?

/**
 * The checks of a vehicle against an order (openTCS's assignment candidate filters). Cheap checks run before the
 * order is routed, the driver is asked last.
 */
internal class CandidateChecks(private val run: DispatchRun, private val availability: VehicleAvailability) {
    private val freeOrderBeforeRouting: List<CandidateFilter> = listOf(::typeAccepted, ::energy, ::dispensableSwap)
    private val freeOrderAfterRouting: List<CandidateFilter> = listOf(::redundancy, ::driver)

    /** Checks a free order for an available vehicle. */
    fun forFreeOrder(candidate: Candidate): Assessment =
        assess(candidate, freeOrderBeforeRouting, freeOrderAfterRouting)

    /**
     * Checks the next order of the vehicle's sequence. The vehicle is committed to the sequence, so its energy and
     * a redundant order do not hold the sequence up.
     */
    fun forSequence(candidate: Candidate): Assessment = assess(candidate, listOf(::typeAccepted), listOf(::driver))

    private fun assess(
        candidate: Candidate,
        beforeRouting: List<CandidateFilter>,
        afterRouting: List<CandidateFilter>,
    ): Assessment {
        beforeRouting.firstRefusal(candidate)?.let { return Assessment.Refused(it) }
        val driveOrders = run.routes.route(candidate.vehicle, candidate.order)
            ?: return Assessment.Refused(refusal(candidate, noRoute(candidate)))
        val routed = candidate.routed(driveOrders)
        afterRouting.firstRefusal(routed)?.let { return Assessment.Refused(it) }
        return Assessment.Accepted(routed)
    }

    // One look at the plant per run, and only once an order found no route: most plants lock no path at all.
    private val anyPathLocked: Boolean by lazy { run.model.paths.any { it.locked } }

    /** Names the locked paths in the way, so that operators know what to unlock. */
    private fun noRoute(candidate: Candidate): String {
        val position = candidate.vehicle.currentPosition ?: return "no route: position unknown"
        val locked = if (anyPathLocked) run.model.lockedPathsOnWay(position, candidate.order) else emptyList()
        val blocking = if (locked.isEmpty()) "" else " (locked path ${locked.joinToString()} blocks the way)"
        return "no route from $position$blocking"
    }

    private fun List<CandidateFilter>.firstRefusal(candidate: Candidate): Refusal? =
        asSequence().mapNotNull { it(candidate) }.firstOrNull()

    private fun typeAccepted(candidate: Candidate): Refusal? {
        val type = candidate.order.type
        if (candidate.vehicle.accepts(type)) return null
        return refusal(candidate, "does not accept type '$type'", "no vehicle accepts type '$type'")
    }

    /** A vehicle with critical energy only takes an order that starts by recharging it. */
    private fun energy(candidate: Candidate): Refusal? {
        val vehicle = candidate.vehicle
        val firstOperation = candidate.order.driveOrders.firstOrNull()?.destination?.operation
        if (!vehicle.isEnergyCritical || firstOperation == vehicle.rechargeOperation) return null
        return refusal(candidate, "energy level critical", "every vehicle's energy level is critical")
    }

    /** Swapping one dispensable order for another would only make the vehicle drive around. */
    private fun dispensableSwap(candidate: Candidate): Refusal? {
        if (!candidate.order.dispensable) return null
        if (availability.dispensableOrder(candidate.vehicle) == null) return null
        return refusal(
            candidate,
            "busy with a dispensable order, which only a non-dispensable one replaces",
            "every vehicle is busy with a dispensable order, which only a non-dispensable one replaces",
        )
    }

    private fun redundancy(candidate: Candidate): Refusal? {
        if (run.configuration.assignRedundantOrders) return null
        val only = candidate.driveOrders.singleOrNull() ?: return null
        val operation = only.destination.operation
        val position = candidate.vehicle.currentPosition
        val idleOperation = operation.startsWith(Operations.NOP) || operation == Operations.MOVE
        if (!idleOperation || only.route?.finalDestinationPoint != position) return null
        return refusal(candidate, "already at $position, where the order does nothing", "order does nothing")
    }

    private fun driver(candidate: Candidate): Refusal? {
        val answer = run.context.driverAccepts(candidate.vehicle.name, candidate.order)
        if (answer.isYes) return null
        val reasons = answer.reasons.joinToString(", ")
        return refusal(candidate, "driver refused: $reasons", "every driver refused: $reasons")
    }

    private fun refusal(candidate: Candidate, detail: String, summary: String = "all vehicles: $detail") =
        Refusal(candidate.vehicle.name, detail, summary)
}
