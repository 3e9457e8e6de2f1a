package org.ktcs.kernel.context

import org.ktcs.api.kernel.KernelClock

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

    /** Runs [block] in the kernel context and returns its result (or throws its exception) to the caller. */
    suspend fun <T> call(block: () -> T): T

    /** Whether the calling code runs in the kernel context. */
    fun isInKernelContext(): Boolean
}
