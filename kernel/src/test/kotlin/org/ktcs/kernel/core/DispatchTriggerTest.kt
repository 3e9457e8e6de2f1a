package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.kernel.context.VirtualTimeKernelContext

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

        context.schedule(0) { trigger.requestForNewOrder() }
        context.schedule(4) { trigger.requestForNewOrder() }
        context.schedule(9) { trigger.requestForNewOrder() }
        context.schedule(15) { trigger.requestForNewOrder() }
        context.runUntilTime(100)

        dispatcher.runsAt shouldBe listOf(10L, 25L)
    }

    test("any other request runs the dispatcher at once, taking the new orders' pending run with it") {
        val (context, setup) = setUp(newOrderDelay = 10)
        val (trigger, dispatcher) = setup

        context.schedule(0) { trigger.requestForNewOrder() }
        context.schedule(3) {
            trigger.request()
            trigger.requestForNewOrder()
        }
        context.runUntilTime(100)

        dispatcher.runsAt shouldBe listOf(3L)
    }

    test("without a delay a new order is dispatched after the current task, as any request") {
        val (context, setup) = setUp(newOrderDelay = 0)
        val (trigger, dispatcher) = setup

        context.schedule(5) {
            trigger.requestForNewOrder()
            trigger.request()
        }
        context.runUntilTime(100)

        dispatcher.runsAt shouldBe listOf(5L)
    }
})
