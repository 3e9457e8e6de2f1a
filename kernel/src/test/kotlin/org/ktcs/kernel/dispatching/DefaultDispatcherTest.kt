package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.kernel.Explained
import org.ktcs.api.order.OrderSequence

class DefaultDispatcherTest : FunSpec({
    test("an assignment the kernel refuses does not keep the other orders from being assigned") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1"), vehicle("V2"), order("T1", deadline = T0), order("T2"))
        context.refusedOrders += "T1"

        context.dispatch()

        context.assignments.map { it.order } shouldContainExactly listOf("T2")
    }

    test("a deferred order is assigned as soon as the reason goes away") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1"), order("T1"))
        val dispatcher = context.dispatcher()
        context.driver = { _, _ -> Explained.no("busy") }

        dispatcher.dispatch()
        context.driver = { _, _ -> Explained.YES }
        dispatcher.dispatch()

        context.deferralsOf("T1") shouldContainExactly listOf("vehicle V1: driver refused: busy")
        context.assignedOrder("V1") shouldBe "T1"
    }

    test("one run does all phases: successors, free orders, recharging and parking") {
        val context = FakeDispatchContext(plant(charger("C1", "B"), park = setOf("H")))
        context.add(vehicle("Seq-V", at = "C").copy(orderSequence = "Seq"), vehicle("Free", at = "D"))
        context.add(vehicle("Low", at = "E", energy = 40), vehicle("Idle", at = "F"))
        context.add(OrderSequence("Seq", T0, orders = listOf("S-1"), processingVehicle = "Seq-V"))
        context.add(order("S-1", sequence = "Seq"), order("T1", load("S1")))

        context.dispatcher(DispatcherConfiguration()).dispatch()

        context.assignments.map { it.vehicle to it.order } shouldContainExactly listOf(
            "Seq-V" to "S-1",
            "Free" to "T1",
            "Low" to "Recharge-01",
            "Idle" to "Park-02",
        )
    }
})
