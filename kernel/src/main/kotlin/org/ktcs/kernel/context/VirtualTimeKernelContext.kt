package org.ktcs.kernel.context

import kotlinx.coroutines.CompletableDeferred
import org.ktcs.api.kernel.Cancellable
import java.time.Instant
import java.util.PriorityQueue

/**
 * The kernel context on virtual time: tasks wait in a queue ordered by due time (then by submission), and the
 * owner of the context runs them with [runUntil] / [runUntilIdle], jumping from one due time to the next. The same
 * inputs give the same results, as fast as the CPU allows.
 *
 * Only the thread that runs the queue is in the kernel context; other threads may submit work at any time.
 */
class VirtualTimeKernelContext(private val start: Instant = Instant.parse("2026-01-01T00:00:00Z")) : KernelContext {
    private class Task(val dueMillis: Long, val sequence: Long, val action: () -> Unit) {
        @Volatile
        var cancelled = false
    }

    private val queue = PriorityQueue(compareBy<Task>({ it.dueMillis }, { it.sequence }))
    private val lock = Object()
    private var sequence = 0L

    @Volatile
    private var nowMillis = 0L

    @Volatile
    private var runner: Thread? = null

    override fun now(): Instant = start.plusMillis(nowMillis)

    override fun elapsedMillis(): Long = nowMillis

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable {
        val task = synchronized(lock) {
            Task(nowMillis + delayMillis.coerceAtLeast(0), sequence++, action).also(queue::add)
        }
        return Cancellable { task.cancelled = true }
    }

    override suspend fun <T> call(block: () -> T): T {
        if (isInKernelContext()) return block()
        val result = CompletableDeferred<T>()
        execute { runCatching(block).fold(result::complete, result::completeExceptionally) }
        return result.await()
    }

    override fun isInKernelContext(): Boolean = Thread.currentThread() === runner

    /** Runs due tasks until [stop] says so or nothing is left; returns whether [stop] was met. */
    fun runUntil(stop: () -> Boolean): Boolean {
        runner = Thread.currentThread()
        try {
            while (!stop()) {
                val task = synchronized(lock) { queue.poll() } ?: return false
                if (task.cancelled) continue
                nowMillis = maxOf(nowMillis, task.dueMillis)
                task.action()
            }
            return true
        } finally {
            runner = null
        }
    }

    /** Runs every task due up to [millis] after the start, then sets the clock there. */
    fun runUntilTime(millis: Long) {
        runUntil { synchronized(lock) { queue.peek()?.dueMillis?.let { it > millis } ?: true } }
        nowMillis = maxOf(nowMillis, millis)
    }

    /** Runs tasks until none is left. Beware of periodic tasks: they never leave the queue empty. */
    fun runUntilIdle() {
        runUntil { false }
    }

    /** How many tasks wait (for tests). */
    internal fun pendingTasks(): Int = synchronized(lock) { queue.count { !it.cancelled } }

    override fun close() {
        synchronized(lock) { queue.clear() }
    }
}
