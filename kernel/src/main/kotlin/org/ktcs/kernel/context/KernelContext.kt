package org.ktcs.kernel.context

import org.ktcs.api.kernel.KernelClock
import kotlin.coroutines.Continuation
import kotlin.coroutines.EmptyCoroutineContext
import kotlin.coroutines.startCoroutine

/**
 * The one context in which all kernel state changes: tasks run one at a time, in the order they are due. Code
 * outside the kernel (web handlers, XML channels, drivers' I/O threads) hands work in with [execute] or [call].
 *
 * Two implementations: [RealTimeKernelContext] for operation, [VirtualTimeKernelContext] for tests and simulations.
 */
interface KernelContext : KernelClock, AutoCloseable {
    /** Runs [task] in the kernel context as soon as possible. */
    fun execute(task: () -> Unit) {
        schedule(0, task)
    }

    /**
     * Runs [task] in the kernel context as soon as possible, for a caller that waits for what [task] does: unlike
     * [execute], which drops a task quietly once the context is closed, it throws then, so that the caller fails
     * instead of waiting for ever.
     */
    fun submit(task: () -> Unit) {
        execute(task)
    }

    /** Runs [block] in the kernel context and returns its result (or throws its exception) to the caller. */
    suspend fun <T> call(block: () -> T): T

    /**
     * Runs [block] in the kernel context as one task, so that no other kernel task runs in between, and returns its
     * result. Kernel services answer at once in the kernel context, so a block that only calls them never suspends;
     * one that does suspend (waiting for another thread) would hold the kernel up and fails with
     * [IllegalStateException] instead. The kernel thread never blocks on it.
     */
    suspend fun <T> callAtomically(block: suspend () -> T): T = call { completedWithoutSuspending(block) }

    /**
     * Runs [task] at once on the calling thread, as a kernel task, if the context is idle (nothing queued, nothing
     * running) and returns `true`; else returns `false` and the caller hands the task in with [submit]. [task] must
     * not throw. A caller who waits for its task anyway saves the hand-off to the kernel thread and back.
     */
    fun runHereIfIdle(task: () -> Unit): Boolean = false

    /** Whether the calling code runs in the kernel context. */
    fun isInKernelContext(): Boolean
}

private fun <T> completedWithoutSuspending(block: suspend () -> T): T {
    var outcome: Result<T>? = null
    block.startCoroutine(Continuation(EmptyCoroutineContext) { outcome = it })
    return checkNotNull(outcome) {
        "a kernel-context block suspended; it may only call kernel services, which answer at once there"
    }.getOrThrow()
}
