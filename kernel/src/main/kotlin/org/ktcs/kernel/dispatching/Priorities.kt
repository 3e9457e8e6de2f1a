package org.ktcs.kernel.dispatching

import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder
import java.time.Instant

/**
 * The rankings of one dispatch run, composed from the configured keys. Each ends with tie-breakers (age and name of
 * orders, name of vehicles), so every ranking is a total order on distinct names.
 */
internal class Priorities(configuration: DispatcherConfiguration, now: Instant) {
    private val atRiskBefore = now.plusMillis(configuration.deadlineAtRiskPeriodMillis)
    private val atRisk: (TransportOrder) -> Boolean = { it.deadline < atRiskBefore }

    val orders: Comparator<TransportOrder> = compose(
        (configuration.orderPriorities + OrderPriority.BY_AGE + OrderPriority.BY_NAME).map {
            orderComparator(it, atRisk)
        },
    )

    val vehicles: Comparator<Vehicle> =
        compose((configuration.vehiclePriorities + VehiclePriority.BY_NAME).map(::vehicleComparator))

    /** For a vehicle choosing among orders. */
    val orderCandidates = CandidateRanking(
        configuration.orderCandidatePriorities,
        listOf(CandidatePriority.BY_AGE, CandidatePriority.BY_ORDER_NAME, CandidatePriority.BY_VEHICLE_NAME),
        atRisk,
    )

    /** For an order choosing among vehicles. */
    val vehicleCandidates = CandidateRanking(
        configuration.vehicleCandidatePriorities,
        listOf(CandidatePriority.BY_VEHICLE_NAME, CandidatePriority.BY_AGE, CandidatePriority.BY_ORDER_NAME),
        atRisk,
    )
}

/**
 * A ranking of candidates by [keys], then [tieBreakers].
 *
 * [beforeRouting] is the part of the ranking that needs no routes: all of it when no key compares route costs,
 * otherwise the keys before the first one that does. Candidates it ranks apart need not both be routed: the better
 * ones are tried first, and only candidates it ranks equal have to be routed together to find the best.
 */
internal class CandidateRanking(
    keys: List<CandidatePriority>,
    tieBreakers: List<CandidatePriority>,
    atRisk: (TransportOrder) -> Boolean,
) {
    val full: Comparator<Candidate> = compose((keys + tieBreakers).map { candidateComparator(it, atRisk) })

    /** The first key that compares route costs, or `null`. */
    val routeKey: CandidatePriority? = keys.firstOrNull { it.needsRoute }

    val beforeRouting: Comparator<Candidate> =
        if (routeKey == null) {
            full
        } else {
            compose(keys.takeWhile { !it.needsRoute }.map { candidateComparator(it, atRisk) })
        }
}

internal fun orderComparator(key: OrderPriority, atRisk: (TransportOrder) -> Boolean): Comparator<TransportOrder> =
    when (key) {
        OrderPriority.BY_AGE -> compareBy { it.creationTime }
        OrderPriority.BY_DEADLINE -> compareBy { it.deadline }
        OrderPriority.DEADLINE_AT_RISK_FIRST -> compareBy { !atRisk(it) }
        OrderPriority.BY_NAME -> compareBy { it.name }
    }

internal fun vehicleComparator(key: VehiclePriority): Comparator<Vehicle> = when (key) {
    VehiclePriority.IDLE_FIRST -> compareBy { it.state != VehicleState.IDLE }
    VehiclePriority.BY_ENERGY_LEVEL -> compareByDescending { it.energyLevel }
    VehiclePriority.BY_NAME -> compareBy { it.name }
}

internal fun candidateComparator(key: CandidatePriority, atRisk: (TransportOrder) -> Boolean): Comparator<Candidate> =
    when (key) {
        CandidatePriority.BY_AGE -> orderComparator(OrderPriority.BY_AGE, atRisk).onOrder()

        CandidatePriority.BY_DEADLINE -> orderComparator(OrderPriority.BY_DEADLINE, atRisk).onOrder()

        CandidatePriority.DEADLINE_AT_RISK_FIRST -> orderComparator(
            OrderPriority.DEADLINE_AT_RISK_FIRST,
            atRisk,
        ).onOrder()

        CandidatePriority.BY_ORDER_NAME -> orderComparator(OrderPriority.BY_NAME, atRisk).onOrder()

        CandidatePriority.IDLE_FIRST -> vehicleComparator(VehiclePriority.IDLE_FIRST).onVehicle()

        CandidatePriority.BY_ENERGY_LEVEL -> vehicleComparator(VehiclePriority.BY_ENERGY_LEVEL).onVehicle()

        CandidatePriority.BY_VEHICLE_NAME -> vehicleComparator(VehiclePriority.BY_NAME).onVehicle()

        CandidatePriority.BY_COMPLETE_ROUTING_COSTS -> compareBy { it.completeCosts }

        CandidatePriority.BY_INITIAL_ROUTING_COSTS -> compareBy { it.initialCosts }

        CandidatePriority.BY_ORDER_TYPE_PRIORITY -> compareBy { it.vehicle.orderTypePriority(it.order.type) }
    }

private fun Comparator<TransportOrder>.onOrder(): Comparator<Candidate> = Comparator { a, b ->
    compare(a.order, b.order)
}

private fun Comparator<Vehicle>.onVehicle(): Comparator<Candidate> = Comparator { a, b ->
    compare(a.vehicle, b.vehicle)
}

private fun <T> compose(comparators: List<Comparator<T>>): Comparator<T> =
    comparators.fold(Comparator { _, _ -> 0 }) { composed, next -> composed.thenComparing(next) }
