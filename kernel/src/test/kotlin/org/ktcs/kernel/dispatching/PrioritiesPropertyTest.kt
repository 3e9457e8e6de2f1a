package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.bind
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.element
import io.kotest.property.arbitrary.enum
import io.kotest.property.arbitrary.int
import io.kotest.property.arbitrary.list
import io.kotest.property.arbitrary.long
import io.kotest.property.arbitrary.map
import io.kotest.property.checkAll
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder
import kotlin.math.sign

class PrioritiesPropertyTest : FunSpec({
    // Small value ranges, so that keys tie often and the tie-breakers are exercised.
    val vehicles = Arb.list(
        Arb.bind(Arb.int(0..2), Arb.enum<VehicleState>(), Arb.int(0..2)) { a, b, c ->
            Triple(a, b, c)
        },
        1..4,
    ).map {
        it.mapIndexed { index, (energy, state, typePriority) ->
            vehicle("V$index", energy = energy * 50, state = state).copy(
                acceptableOrderTypes = setOf(
                    AcceptableOrderType("Transport", typePriority),
                    AcceptableOrderType("*", 1),
                ),
            )
        }
    }
    val orders = Arb.list(
        Arb.bind(Arb.long(0L..2L), Arb.long(0L..2L), Arb.element("Transport", "Park")) { a, b, c ->
            Triple(a, b, c)
        },
        1..4,
    ).map {
        it.mapIndexed { index, (age, deadline, type) ->
            order("O$index", type = type, created = T0.minusSeconds(age * 60), deadline = T0.plusSeconds(deadline * 50))
        }
    }
    val keys = Arb.list(Arb.enum<CandidatePriority>(), 0..4)
    val costs = Arb.list(Arb.long(0L..2L), 16..16)

    fun candidates(vehicles: List<Vehicle>, orders: List<TransportOrder>, costs: List<Long>) =
        vehicles.flatMap { vehicle -> orders.map { Candidate(vehicle, it) } }.mapIndexed { index, candidate ->
            val route = Route(emptyList(), costs[index % costs.size])
            candidate.routed(
                listOf(
                    DriveOrder("Drive-0", load("S1"), route = route),
                    DriveOrder("Drive-1", load("S2"), route = route),
                ),
            )
        }

    fun <T> shouldBeTotalOrder(items: List<T>, comparator: Comparator<T>, identity: (T) -> Any) {
        for (a in items) {
            for (b in items) {
                comparator.compare(a, b).sign shouldBe -comparator.compare(b, a).sign
                (comparator.compare(a, b) == 0) shouldBe (identity(a) == identity(b))
                for (c in items) {
                    if (comparator.compare(a, b) <= 0 && comparator.compare(b, c) <= 0) {
                        (comparator.compare(a, c) <= 0) shouldBe true
                    }
                }
            }
        }
        items.shuffled().sortedWith(comparator).map(identity) shouldBe items.sortedWith(comparator).map(identity)
    }

    test("candidate rankings are total orders on vehicle and order names, whatever the keys") {
        checkAll(300, vehicles, orders, keys, costs) { vehicles, orders, keys, costs ->
            val configuration =
                DispatcherConfiguration(orderCandidatePriorities = keys, vehicleCandidatePriorities = keys)
            val priorities = Priorities(configuration, T0)
            val all = candidates(vehicles, orders, costs)
            shouldBeTotalOrder(all, priorities.orderCandidates.full) { it.vehicle.name to it.order.name }
            shouldBeTotalOrder(all, priorities.vehicleCandidates.full) { it.vehicle.name to it.order.name }
        }
    }

    test("order and vehicle rankings are total orders on names, whatever the keys") {
        checkAll(
            300,
            vehicles,
            orders,
            Arb.list(Arb.enum<OrderPriority>(), 0..4),
            Arb.list(
                Arb.enum<VehiclePriority>(),
                0..3,
            ),
        ) { vehicles, orders, orderKeys, vehicleKeys ->
            val priorities =
                Priorities(DispatcherConfiguration(orderPriorities = orderKeys, vehiclePriorities = vehicleKeys), T0)
            shouldBeTotalOrder(orders, priorities.orders) { it.name }
            shouldBeTotalOrder(vehicles, priorities.vehicles) { it.name }
        }
    }

    test("the ranking before routing never contradicts the full ranking") {
        checkAll(300, vehicles, orders, keys, costs) { vehicles, orders, keys, costs ->
            val ranking = Priorities(DispatcherConfiguration(orderCandidatePriorities = keys), T0).orderCandidates
            val all = candidates(vehicles, orders, costs)
            for (a in all) {
                for (b in all) {
                    if (ranking.beforeRouting.compare(a, b) < 0) {
                        (ranking.full.compare(a, b) < 0) shouldBe true
                    }
                }
            }
        }
    }

    test("the lazy search finds the same candidate as ranking all accepted ones, with or without cost bounds") {
        checkAll(300, vehicles, orders, keys, costs, Arb.list(Arb.boolean(), 16..16)) {
                vehicles,
                orders,
                keys,
                costs,
                accepts,
            ->
            val ranking = Priorities(DispatcherConfiguration(orderCandidatePriorities = keys), T0).orderCandidates
            val routed = candidates(vehicles, orders, costs)
            val accepted = routed.filterIndexed { index, _ -> accepts[index] }
            val unrouted = routed.map { Candidate(it.vehicle, it.order) }.shuffled()
            val byPair = accepted.associateBy { it.vehicle.name to it.order.name }

            val found = bestCandidate(unrouted, ranking, { byPair[it.vehicle.name to it.order.name] })
            // The costs of the route to the first destination bound both route-cost keys from below, tightly.
            val costsByPair = routed.associate { (it.vehicle.name to it.order.name) to it.initialCosts }
            val bounded = bestCandidate(unrouted, ranking, { byPair[it.vehicle.name to it.order.name] }) {
                costsByPair[it.vehicle.name to it.order.name]
            }

            found?.toString() shouldBe accepted.minWithOrNull(ranking.full)?.toString()
            bounded?.toString() shouldBe found?.toString()
        }
    }
})
