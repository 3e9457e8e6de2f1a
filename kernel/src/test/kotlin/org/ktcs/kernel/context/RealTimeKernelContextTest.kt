package org.ktcs.kernel.context

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import java.util.concurrent.RejectedExecutionException

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

    test("an atomic call runs its service calls in one kernel task without blocking the kernel thread") {
        val context = RealTimeKernelContext()
        val ran = mutableListOf<Int>()
        val result = context.callAtomically {
            context.execute { ran += 2 }
            context.call { ran += 1 }
            context.call { ran.toList() }
        }

        result shouldBe listOf(1)
        context.call { ran.toList() } shouldBe listOf(1, 2)
        context.close()
    }

    test("an atomic call that waits for another thread fails clearly instead of deadlocking the kernel") {
        val context = RealTimeKernelContext()

        val error = shouldThrow<IllegalStateException> {
            withTimeout(5_000) {
                context.callAtomically { withContext(Dispatchers.Default) { context.call { 1 } } }
            }
        }

        error.message shouldContain "suspended"
        context.call { context.isInKernelContext() } shouldBe true
        context.close()
    }

    test("a task scheduled once the context has closed is dropped quietly instead of failing the caller") {
        val context = RealTimeKernelContext()
        context.close()

        val dropped = runCatching { context.schedule(0) { error("must not run") } }

        dropped.isSuccess shouldBe true
        dropped.getOrThrow().cancel()
    }

    test("a task a caller waits for, submitted once the context has closed, fails the caller instead of vanishing") {
        val context = RealTimeKernelContext()
        context.close()

        shouldThrow<RejectedExecutionException> { context.submit { error("must not run") } }
    }
})
