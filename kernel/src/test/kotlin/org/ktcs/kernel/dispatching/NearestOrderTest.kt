package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState

/**
 * The default choice of a vehicle that becomes free: the nearest order among the most urgent ones it may take
 * (`orderCandidatePriorities` BY_DEADLINE, BY_INITIAL_ROUTING_COSTS within `orderCandidateWindow`), and no order
 * passed over more often than the window is large.
 */
class NearestOrderTest : FunSpec({
    /** What V1, standing at G next to S2, takes: [other] (at S1, farther away) or an order at S2 created at T0. */
    fun choiceBetween(other: TransportOrder, configuration: DispatcherConfiguration = assignOnly): String? {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1", at = "G"), other, order("Near", load("S2")))
        context.dispatch(configuration)
        return context.assignedOrder("V1")
    }

    test("a vehicle that becomes free takes the nearest order, not the oldest") {
        choiceBetween(order("Old", load("S1"), created = T0.minusSeconds(60))) shouldBe "Near"
    }

    test("an earlier deadline still comes before distance") {
        choiceBetween(order("Urgent", load("S1"), deadline = T0.plusSeconds(60))) shouldBe "Urgent"
    }

    test("the vehicle chooses only among the window of longest-waiting orders") {
        val oldest = order("Oldest", load("S1"), created = T0.minusSeconds(60))
        choiceBetween(oldest, assignOnly.copy(orderCandidateWindow = 1)) shouldBe "Oldest"
    }

    test("by default the vehicle chooses among the 50 longest-waiting orders") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1", at = "G"))
        val old = (1..49).map { order("Old$it", load("S1"), created = T0.minusSeconds(60L - it)) }
        context.add(*old.toTypedArray(), order("Near", load("S2")))

        context.dispatch(assignOnly)

        context.assignedOrder("V1") shouldBe "Near"
    }

    test("with window 0 the vehicle chooses among all orders, as openTCS does") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1", at = "G"))
        val old = (1..3).map { order("Old$it", load("S1"), created = T0.minusSeconds(60L - it)) }
        context.add(*old.toTypedArray(), order("Near", load("S2")))

        context.dispatch(assignOnly.copy(orderCandidateWindow = 0))

        context.assignedOrder("V1") shouldBe "Near"
    }

    test("an order passed over as often as the window is large is taken next, although nearer ones wait") {
        val context = FakeDispatchContext(plant())
        val dispatcher = context.dispatcher(assignOnly.copy(orderCandidateWindow = 3))
        context.add(order("Far", load("S1"), created = T0.minusSeconds(60)))
        val nearOnes = (1..6).map { order("Near$it", load("S2"), created = T0.plusSeconds(it.toLong())) }
        context.add(*nearOnes.toTypedArray())
        // The vehicle stands at G, next to S2 (at F), each time it becomes free.
        repeat(4) {
            context.add(vehicle("V1", at = "G"))
            dispatcher.dispatch()
            val taken = context.assignedTo("V1").last()
            context.add(context.orders.getValue(taken).copy(state = TransportOrderState.FINISHED))
        }

        context.assignedTo("V1") shouldContainExactly listOf("Near1", "Near2", "Near3", "Far")
    }

    test("an order ranking vehicles by routing costs takes the nearest, routing only it") {
        val context = FakeDispatchContext(plant())
        // S2 is at F: the vehicle at G is one path away, those at D and H two, the others more.
        val at = mapOf("V1" to "A", "V2" to "B", "V3" to "H", "V4" to "D", "V5" to "G")
        context.add(*at.map { (name, point) -> vehicle(name, at = point) }.toTypedArray(), order("T", load("S2")))
        val nearest = listOf(CandidatePriority.IDLE_FIRST, CandidatePriority.BY_INITIAL_ROUTING_COSTS)

        context.dispatch(assignOnly.copy(vehicleCandidatePriorities = nearest))

        context.assignedOrder("V5") shouldBe "T"
        context.router.routeOrderCalls shouldBe 1
    }
})
