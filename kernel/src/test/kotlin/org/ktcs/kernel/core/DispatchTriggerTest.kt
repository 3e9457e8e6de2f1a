package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.dispatching.IncrementalDispatcher

class DispatchTriggerTest : FunSpec({
    class CountingDispatcher(private val context: VirtualTimeKernelContext) : Dispatcher {
        val runsAt = mutableListOf<Long>()

        override fun dispatch() {
            runsAt += context.elapsedMillis()
        }
    }

    fun setUp(newOrderDelay: Long): Pair<VirtualTimeKernelContext, Pair<DispatchTrigger, CountingDispatcher>> {
        val context = VirtualTimeKernelContext()
        val dispatcher = CountingDispatcher(context)
        return context to (DispatchTrigger(context, { dispatcher }, periodMillis = 0, newOrderDelay) to dispatcher)
    }

    test("orders created within the delay share one run, due the delay after the first") {
        val (context, setup) = setUp(newOrderDelay = 10)
        val (trigger, dispatcher) = setup

        context.schedule(0) { trigger.requestForNewOrder("T") }
        context.schedule(4) { trigger.requestForNewOrder("T") }
        context.schedule(9) { trigger.requestForNewOrder("T") }
        context.schedule(15) { trigger.requestForNewOrder("T") }
        context.runUntilTime(100)

        dispatcher.runsAt shouldBe listOf(10L, 25L)
    }

    test("any other request runs the dispatcher at once, taking the new orders' pending run with it") {
        val (context, setup) = setUp(newOrderDelay = 10)
        val (trigger, dispatcher) = setup

        context.schedule(0) { trigger.requestForNewOrder("T") }
        context.schedule(3) {
            trigger.request()
            trigger.requestForNewOrder("T")
        }
        context.runUntilTime(100)

        dispatcher.runsAt shouldBe listOf(3L)
    }

    test("without a delay a new order is dispatched after the current task, as any request") {
        val (context, setup) = setUp(newOrderDelay = 0)
        val (trigger, dispatcher) = setup

        context.schedule(5) {
            trigger.requestForNewOrder("T")
            trigger.request()
        }
        context.runUntilTime(100)

        dispatcher.runsAt shouldBe listOf(5L)
    }

    class RecordingDispatcher : IncrementalDispatcher {
        val runs = mutableListOf<String>()

        override fun dispatch() {
            runs += "full"
        }

        override fun dispatchChanges(newOrders: Collection<String>) {
            runs += "changes $newOrders"
        }
    }

    test("a run asked for by new orders and vehicles only is a run on changes, given the new orders") {
        val context = VirtualTimeKernelContext()
        val dispatcher = RecordingDispatcher()
        val trigger = DispatchTrigger(context, { dispatcher }, periodMillis = 0, newOrderDelayMillis = 10)

        context.schedule(0) {
            trigger.requestForNewOrder("T1")
            trigger.requestForNewOrder("T2")
        }
        context.schedule(20) { trigger.requestForVehicle() }
        context.schedule(30) {
            trigger.requestForNewOrder("T3")
            trigger.requestForVehicle()
        }
        context.schedule(40) {
            trigger.requestForNewOrder("T4")
            trigger.request()
        }
        context.schedule(50) { trigger.requestForNewOrder("T5") }
        context.runUntilTime(100)

        dispatcher.runs shouldBe listOf("changes [T1, T2]", "changes []", "changes [T3]", "full", "changes [T5]")
    }
})
