package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder

class PrioritiesTest : FunSpec({
    fun priorities(configuration: DispatcherConfiguration = DispatcherConfiguration()) = Priorities(configuration, T0)

    fun List<TransportOrder>.rankedBy(vararg keys: OrderPriority) =
        sortedWith(priorities(DispatcherConfiguration(orderPriorities = keys.toList())).orders).map { it.name }

    fun List<Vehicle>.rankedBy(vararg keys: VehiclePriority) =
        sortedWith(priorities(DispatcherConfiguration(vehiclePriorities = keys.toList())).vehicles).map { it.name }

    fun List<Candidate>.rankedBy(vararg keys: CandidatePriority) =
        sortedWith(priorities(DispatcherConfiguration(orderCandidatePriorities = keys.toList())).orderCandidates.full)
            .map { it.order.name }

    fun routedCosts(vararg costs: Long) = costs.mapIndexed { index, it ->
        DriveOrder("Drive-$index", load("S1"), route = Route(emptyList(), it))
    }

    context("orders") {
        val young = order("Young", created = T0, deadline = T0.plusSeconds(30))
        val old = order("Old", created = T0.minusSeconds(600), deadline = T0.plusSeconds(3600))
        val beta = order("Beta", created = T0.minusSeconds(60), deadline = T0.plusSeconds(120))

        test("BY_AGE puts the oldest first") {
            listOf(young, old, beta).rankedBy(OrderPriority.BY_AGE) shouldContainExactly
                listOf("Old", "Beta", "Young")
        }

        test("BY_DEADLINE puts the earliest deadline first") {
            listOf(old, beta, young).rankedBy(OrderPriority.BY_DEADLINE) shouldContainExactly
                listOf("Young", "Beta", "Old")
        }

        test("DEADLINE_AT_RISK_FIRST puts orders due within the period first, then falls back to age") {
            listOf(old, beta, young).rankedBy(OrderPriority.DEADLINE_AT_RISK_FIRST) shouldContainExactly
                listOf("Young", "Old", "Beta")
        }

        test("BY_NAME sorts lexicographically") {
            listOf(young, old, beta).rankedBy(OrderPriority.BY_NAME) shouldContainExactly listOf("Beta", "Old", "Young")
        }
    }

    context("vehicles") {
        val charging = vehicle("A-Charging", energy = 100, state = VehicleState.CHARGING)
        val full = vehicle("B-Full", energy = 100)
        val half = vehicle("C-Half", energy = 50)

        test("IDLE_FIRST puts vehicles in state IDLE first, then sorts by name") {
            listOf(charging, half, full).rankedBy(VehiclePriority.IDLE_FIRST) shouldContainExactly
                listOf("B-Full", "C-Half", "A-Charging")
        }

        test("BY_ENERGY_LEVEL puts the fullest first") {
            listOf(half, full, charging).rankedBy(VehiclePriority.BY_ENERGY_LEVEL) shouldContainExactly
                listOf("A-Charging", "B-Full", "C-Half")
        }

        test("the defaults combine both") {
            listOf(half, charging, full).sortedWith(priorities().vehicles).map { it.name } shouldContainExactly
                listOf("B-Full", "C-Half", "A-Charging")
        }
    }

    context("candidates") {
        val vehicle = vehicle("V1").copy(
            acceptableOrderTypes = setOf(AcceptableOrderType("Transport", 2), AcceptableOrderType("*", 5)),
        )
        val near = Candidate(vehicle, order("Near", type = "Other", created = T0), routedCosts(100, 900))
        val far = Candidate(vehicle, order("Far", type = "Transport", created = T0.plusSeconds(1)), routedCosts(800, 1))

        test("BY_COMPLETE_ROUTING_COSTS and BY_INITIAL_ROUTING_COSTS compare the sums and the first routes") {
            listOf(near, far).rankedBy(CandidatePriority.BY_COMPLETE_ROUTING_COSTS) shouldContainExactly
                listOf("Far", "Near")
            listOf(far, near).rankedBy(CandidatePriority.BY_INITIAL_ROUTING_COSTS) shouldContainExactly
                listOf("Near", "Far")
        }

        test("BY_ORDER_TYPE_PRIORITY prefers a type the vehicle names over '*'") {
            listOf(near, far).rankedBy(CandidatePriority.BY_ORDER_TYPE_PRIORITY) shouldContainExactly
                listOf("Far", "Near")
            vehicle.orderTypePriority("Unknown") shouldBe 5
            vehicle("V2").copy(acceptableOrderTypes = emptySet()).orderTypePriority("Transport") shouldBe Int.MAX_VALUE
        }

        test("order keys and vehicle keys rank candidates by their order and their vehicle") {
            listOf(far, near).rankedBy(CandidatePriority.BY_AGE) shouldContainExactly listOf("Near", "Far")
            listOf(near, far).rankedBy(CandidatePriority.BY_ORDER_NAME) shouldContainExactly listOf("Far", "Near")
            val weak = Candidate(vehicle("W", energy = 10, state = VehicleState.CHARGING), order("T"))
            val strong = Candidate(vehicle("S", energy = 90), order("T"))
            val byVehicle = { key: CandidatePriority ->
                listOf(weak, strong).sortedWith(
                    priorities(
                        DispatcherConfiguration(vehicleCandidatePriorities = listOf(key)),
                    ).vehicleCandidates.full,
                ).map { it.vehicle.name }
            }
            byVehicle(CandidatePriority.IDLE_FIRST) shouldContainExactly listOf("S", "W")
            byVehicle(CandidatePriority.BY_ENERGY_LEVEL) shouldContainExactly listOf("S", "W")
            byVehicle(CandidatePriority.BY_VEHICLE_NAME) shouldContainExactly listOf("S", "W")
        }

        test("keys that need no route make the ranking before routing the full ranking") {
            val ranking = priorities().vehicleCandidates
            ranking.beforeRouting shouldBe ranking.full
        }
    }
})
