package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * Gives each vehicle bound to an order sequence the sequence's next order once that is dispatchable (openTCS's
 * `AssignSequenceSuccessorsPhase`), when the vehicle is idle or only busy with a dispensable order of the sequence.
 */
internal class SequenceSuccessors(
    private val run: DispatchRun,
    private val availability: VehicleAvailability,
    private val checks: CandidateChecks,
    private val deferrals: DeferralLog,
) {
    fun assign() {
        run.vehicles.filter(::isReady).forEach(::assignSuccessor)
    }

    private fun isReady(vehicle: Vehicle): Boolean = vehicle.orderSequence
        ?.let { availability.isAvailable(vehicle, VehicleAvailability.Work(sequence = it)) } == true

    private fun assignSuccessor(vehicle: Vehicle) {
        val sequence = vehicle.orderSequence?.let(run::sequence) ?: return
        val next = successor(sequence, vehicle) ?: return
        when (val assessment = checks.forSequence(Candidate(vehicle, next))) {
            is Assessment.Accepted -> if (run.assign(assessment.candidate)) deferrals.assigned(next.name)
            is Assessment.Refused -> deferrals.record(next.name, describe(listOf(assessment.refusal)))
        }
    }

    /** The first unfinished order after the vehicle's current one, if it is dispatchable. */
    private fun successor(sequence: OrderSequence, vehicle: Vehicle): TransportOrder? = sequence.orders
        .drop(sequence.finishedIndex + 1)
        .asSequence()
        .filter { it != vehicle.transportOrder }
        .mapNotNull(run::order)
        .firstOrNull { !it.state.isFinal }
        ?.takeIf { it.state == TransportOrderState.DISPATCHABLE && !run.isAssigned(it) }
}
