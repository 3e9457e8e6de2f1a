package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.TransportOrderState

class IncrementalDispatchTest : FunSpec({
    test("a run in which no vehicle is available does not read the waiting orders") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1").processing("Busy"), order("Busy", state = TransportOrderState.BEING_PROCESSED))
        context.add(*(1..100).map { order("T$it") }.toTypedArray())

        context.dispatcher().dispatch()

        context.dispatchableReads shouldBe 0
        context.assignments shouldBe emptyList()
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
        context.dispatchableReads shouldBe 1
    }
})
