package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrderState

class AssignmentStrategyTest : FunSpec({
    context("more vehicles than orders: each order picks its vehicle") {
        test("an idle vehicle before a charging one, then the one with more energy") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1", energy = 100, state = VehicleState.CHARGING), vehicle("V2", energy = 50))
            context.add(vehicle("V3", energy = 80), order("T1"))

            context.dispatch()

            context.assignedOrder("V3") shouldBe "T1"
        }

        test("orders pick in deadline order, so the most urgent gets the best vehicle") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("Weak", energy = 50), vehicle("Strong", energy = 100))
            context.add(order("Later", deadline = T0.plusSeconds(600)), order("Soon", deadline = T0.plusSeconds(60)))

            context.dispatch()

            context.assignedOrder("Strong") shouldBe "Soon"
            context.assignedOrder("Weak") shouldBe "Later"
        }

        test("with BY_COMPLETE_ROUTING_COSTS the closest vehicle wins") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("Far", at = "A"), vehicle("Near", at = "G"), order("T1", load("S2")))

            val byCosts = listOf(CandidatePriority.BY_COMPLETE_ROUTING_COSTS)
            context.dispatch(assignOnly.copy(vehicleCandidatePriorities = byCosts))

            context.assignedOrder("Near") shouldBe "T1"
        }

        test("an order whose deadline is at risk goes first, before an older one") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("Weak", energy = 50), vehicle("Strong", energy = 100))
            context.add(order("Old", created = T0.minusSeconds(60), deadline = T0.plusSeconds(3600)))
            context.add(order("Urgent", created = T0, deadline = T0.plusSeconds(30)))

            val atRiskFirst = listOf(OrderPriority.DEADLINE_AT_RISK_FIRST, OrderPriority.BY_AGE)
            context.dispatch(assignOnly.copy(orderPriorities = atRiskFirst))

            context.assignedOrder("Strong") shouldBe "Urgent"
        }
    }

    context("fewer vehicles than orders: each vehicle picks its order") {
        test("the vehicle takes the order with the earliest deadline") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1"))
            context.add(order("T1", deadline = T0.plusSeconds(900)), order("T2", deadline = T0.plusSeconds(300)))

            context.dispatch()

            context.assignedOrder("V1") shouldBe "T2"
        }

        test("vehicles pick in priority order, so the one with most energy gets the most urgent order") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("Weak", energy = 50), vehicle("Strong", energy = 100))
            context.add(order("T1", deadline = T0.plusSeconds(100)), order("T2", deadline = T0.plusSeconds(200)))
            context.add(order("T3", deadline = T0.plusSeconds(300)))

            context.dispatch()

            context.assignedOrder("Strong") shouldBe "T1"
            context.assignedOrder("Weak") shouldBe "T2"
        }

        test("with BY_INITIAL_ROUTING_COSTS the vehicle takes the closest order") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1", at = "G"), order("Far", load("S1")), order("Near", load("S2")))

            val byCosts = listOf(CandidatePriority.BY_INITIAL_ROUTING_COSTS)
            context.dispatch(assignOnly.copy(orderCandidatePriorities = byCosts))

            context.assignedOrder("V1") shouldBe "Near"
        }
    }

    context("dispensable orders") {
        test("a vehicle busy with a dispensable order takes a real one, which withdraws the dispensable") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1").processing("Park-01"), order("T1"))
            context.add(order("Park-01", moveTo("H"), dispensable = true, state = TransportOrderState.BEING_PROCESSED))

            context.dispatch()

            context.assignedOrder("V1") shouldBe "T1"
            context.withdrawn shouldContainExactly listOf("Park-01")
        }

        test("an idle vehicle is preferred to one busy with a dispensable order") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("Parking", energy = 100).processing("Park-01"), vehicle("Idle", energy = 60))
            context.add(order("T1"))
            context.add(order("Park-01", moveTo("H"), dispensable = true, state = TransportOrderState.BEING_PROCESSED))

            context.dispatch()

            context.assignedOrder("Idle") shouldBe "T1"
            context.withdrawn.shouldBeEmpty()
        }

        test("a vehicle busy with a dispensable order does not swap it for another dispensable one") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1").processing("Park-01"), order("Park-02", moveTo("B"), dispensable = true))
            context.add(order("Park-01", moveTo("H"), dispensable = true, state = TransportOrderState.BEING_PROCESSED))

            context.dispatch()

            context.assignments.shouldBeEmpty()
        }
    }

    context("work per run") {
        fun manyOrders(context: FakeDispatchContext) = (1..10).forEach {
            val station = if (it % 2 == 0) "S1" else "S2"
            val created = T0.plusSeconds(it.toLong())
            context.add(order("T$it", load(station), created = created, deadline = T0.plusSeconds(it * 60L)))
        }

        test("with deadline ranking only the best order is routed") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1"))
            manyOrders(context)

            context.dispatch()

            context.assignedOrder("V1") shouldBe "T1"
            context.router.routeOrderCalls shouldBe 1
        }

        test("a refused candidate makes the search try the next one, not all") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1"))
            manyOrders(context)
            context.driver = { _, order -> if (order.name == "T1") Explained.no("full") else Explained.YES }

            context.dispatch()

            context.assignedOrder("V1") shouldBe "T2"
            context.router.routeOrderCalls shouldBe 2
        }

        test("ranking by routing costs routes only the candidates that may be the best, each once") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1", at = "C"))
            manyOrders(context)

            val byCosts = listOf(CandidatePriority.BY_COMPLETE_ROUTING_COSTS)
            context.dispatch(assignOnly.copy(orderCandidatePriorities = byCosts))

            context.assignedOrder("V1") shouldBe "T2"
            // The five orders at S1, where V1 stands; the route to S2 alone costs more than theirs.
            context.router.routeOrderCalls shouldBe 5
        }

        test("no vehicle available means no routing at all") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1").copy(paused = true))
            manyOrders(context)

            context.dispatch()

            context.assignedOrder("V1").shouldBeNull()
            context.router.routeOrderCalls shouldBe 0
        }
    }
})
