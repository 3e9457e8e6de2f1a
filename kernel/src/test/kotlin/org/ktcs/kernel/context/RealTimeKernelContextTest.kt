package org.ktcs.kernel.context

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

class RealTimeKernelContextTest : FunSpec({
    test("tasks run in order on the kernel thread") {
        val context = RealTimeKernelContext()
        val ran = mutableListOf<Int>()
        context.schedule(0) { ran += 1 }
        context.schedule(0) { ran += 2 }
        context.call { context.isInKernelContext() } shouldBe true
        context.call { ran.toList() } shouldBe listOf(1, 2)
        context.close()
    }

    test("a task scheduled once the context has closed is dropped quietly instead of failing the caller") {
        val context = RealTimeKernelContext()
        context.close()

        val dropped = runCatching { context.schedule(0) { error("must not run") } }

        dropped.isSuccess shouldBe true
        dropped.getOrThrow().cancel()
    }
})
