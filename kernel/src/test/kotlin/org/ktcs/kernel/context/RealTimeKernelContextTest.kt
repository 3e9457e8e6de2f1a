package org.ktcs.kernel.context

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import java.util.Collections
import java.util.concurrent.CountDownLatch
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.atomic.AtomicInteger

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

    test("the kernel thread asks for the highest priority (applied by the JVM with ThreadPriorityPolicy=1, as root)") {
        val context = RealTimeKernelContext()
        val ran = CountDownLatch(1)
        var priority = 0
        context.schedule(1) {
            priority = Thread.currentThread().priority
            ran.countDown()
        }
        ran.await()
        priority shouldBe Thread.MAX_PRIORITY
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

    test("a caller finding the context idle runs its call itself, as a kernel task") {
        val context = RealTimeKernelContext()
        val caller = Thread.currentThread()

        val ranOn = context.call { Thread.currentThread() to context.isInKernelContext() }

        ranOn shouldBe (caller to true)
        context.isInKernelContext() shouldBe false
        context.close()
    }

    test("a call finding the context busy waits its turn on the kernel thread, after the tasks before it") {
        val context = RealTimeKernelContext()
        val release = CountDownLatch(1)
        val ran = Collections.synchronizedList(mutableListOf<String>())
        context.execute {
            release.await()
            ran += "first"
        }
        context.execute { ran += "second" }

        // Started undispatched, the call finds the context busy and queues before the first task is released.
        val waiting = async(start = CoroutineStart.UNDISPATCHED) {
            context.call { Thread.currentThread().name.also { ran += "call" } }
        }
        release.countDown()

        waiting.await() shouldBe "kernel"
        ran shouldBe listOf("first", "second", "call")
        context.close()
    }

    test("tasks handed in while a caller runs its own run after it, in order") {
        val context = RealTimeKernelContext()
        val ran = Collections.synchronizedList(mutableListOf<String>())

        context.call {
            context.execute { ran += "queued 1" }
            context.execute { ran += "queued 2" }
            ran += "own"
        }

        withTimeout(5_000) { context.call { ran.toList() } } shouldBe listOf("own", "queued 1", "queued 2")
        context.close()
    }

    test("callers on many threads, the kernel thread and its timers never run two tasks at once") {
        val context = RealTimeKernelContext()
        val inside = AtomicInteger()
        val overlaps = AtomicInteger()
        var count = 0 // deliberately unsynchronized: the context alone must order the increments
        val task: () -> Unit = {
            if (inside.incrementAndGet() != 1) overlaps.incrementAndGet()
            count++
            inside.decrementAndGet()
        }

        coroutineScope {
            repeat(8) {
                launch(Dispatchers.Default) {
                    repeat(5_000) { index ->
                        when (index % 3) {
                            0 -> context.call(task)
                            1 -> context.execute(task)
                            else -> context.schedule(1) { task() }
                        }
                    }
                }
            }
        }
        // The timers' tasks come last; a lost increment keeps the count short of all of them.
        withTimeout(10_000) { while (context.call { count } < 40_000) delay(10) }

        context.call { count } shouldBe 40_000
        overlaps.get() shouldBe 0
        context.close()
    }

    test("a task handed in without delay can still be cancelled before it runs") {
        val context = RealTimeKernelContext()
        val release = CountDownLatch(1)
        var ran = false
        context.execute { release.await() }

        context.schedule(0) { ran = true }.cancel()
        release.countDown()

        context.call { ran } shouldBe false
        context.close()
    }
})
