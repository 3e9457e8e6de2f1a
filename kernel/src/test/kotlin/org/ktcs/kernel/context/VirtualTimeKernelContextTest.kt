package org.ktcs.kernel.context

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

class VirtualTimeKernelContextTest : FunSpec({
    test("runs tasks in due order, then submission order, jumping the clock from one to the next") {
        val context = VirtualTimeKernelContext()
        val ran = mutableListOf<String>()
        context.schedule(500) { ran += "b@${context.elapsedMillis()}" }
        context.schedule(100) { ran += "a@${context.elapsedMillis()}" }
        context.schedule(500) { ran += "c@${context.elapsedMillis()}" }

        context.runUntilIdle()

        ran shouldBe listOf("a@100", "b@500", "c@500")
    }

    test("a cancelled task does not run, and runUntilTime stops at the given time") {
        val context = VirtualTimeKernelContext()
        val ran = mutableListOf<Long>()
        context.schedule(10) { ran += 10 }.cancel()
        context.schedule(20) { ran += 20 }
        context.schedule(40) { ran += 40 }

        context.runUntilTime(30)

        ran shouldBe listOf(20L)
        context.elapsedMillis() shouldBe 30
        context.pendingTasks() shouldBe 1
    }
})
