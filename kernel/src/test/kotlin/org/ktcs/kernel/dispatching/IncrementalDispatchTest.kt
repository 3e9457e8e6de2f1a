package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.TransportOrderState

class IncrementalDispatchTest : FunSpec({
    test("while every vehicle stays busy, runs add nothing to the waiting orders' histories") {
        val context = FakeDispatchContext(plant())
        val dispatcher = context.dispatcher()
        context.add(vehicle("V1").processing("Busy"), order("Busy", state = TransportOrderState.BEING_PROCESSED))
        context.add(*(1..100).map { order("T$it") }.toTypedArray())
        dispatcher.dispatch()
        context.deferrals.size shouldBe 100

        context.add(vehicle("V1").processing("Busy2"), order("Busy2", state = TransportOrderState.BEING_PROCESSED))
        dispatcher.dispatch()

        context.deferrals.size shouldBe 100
        context.deferralsOf("T1") shouldBe listOf("every vehicle is busy with an order: V1")
        context.assignments shouldBe emptyList()
    }

    test("a vehicle taking the next order adds nothing to the histories of the orders still waiting") {
        val context = FakeDispatchContext(plant())
        val dispatcher = context.dispatcher()
        context.add(vehicle("V1").processing("Busy1"), order("Busy1", state = TransportOrderState.BEING_PROCESSED))
        context.add(vehicle("V2").processing("Busy2"), order("Busy2", state = TransportOrderState.BEING_PROCESSED))
        context.add(*(1..5).map { order("T$it") }.toTypedArray())
        dispatcher.dispatch()

        context.add(vehicle("V2"), order("Busy2", state = TransportOrderState.FINISHED))
        dispatcher.dispatch()

        context.assignedOrder("V2") shouldBe "T1"
        (2..5).forEach { context.deferralsOf("T$it") shouldBe listOf("every vehicle is busy with an order: V1, V2") }
    }

    test("an order that became dispatchable while the vehicles were busy is assigned once one is free") {
        val context = FakeDispatchContext(plant())
        val dispatcher = context.dispatcher()
        context.add(vehicle("V1").processing("Busy"), order("Busy", state = TransportOrderState.BEING_PROCESSED))
        context.add(order("T1"))
        dispatcher.dispatch()
        context.assignments shouldBe emptyList()

        context.add(vehicle("V1"), order("Busy", state = TransportOrderState.FINISHED))
        dispatcher.dispatch()

        context.assignedOrder("V1") shouldBe "T1"
    }
})
