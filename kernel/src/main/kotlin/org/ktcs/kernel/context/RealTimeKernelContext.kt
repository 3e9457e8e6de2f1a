package org.ktcs.kernel.context

import kotlinx.coroutines.CompletableDeferred
import org.ktcs.api.kernel.Cancellable
import org.slf4j.LoggerFactory
import java.time.Clock
import java.time.Instant
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.Executors
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicInteger

/**
 * The kernel context on the wall clock. Tasks run one at a time, in the order they were handed in, on one thread
 * named `kernel`; except that a caller who waits for its task ([call], [runHereIfIdle]) runs it itself when the
 * context is idle. A request then needs no hand-off to the kernel thread and back, which on a two-core machine is
 * most of a small request's latency.
 *
 * Mutual exclusion comes from [pending], not from the thread: it counts the queued tasks plus one while a thread
 * runs tasks, and only the thread that took it from 0 runs any. Whoever finds the context busy queues its task for
 * the thread running tasks, which runs the queue empty, or hands it to the kernel thread if it ran its own task only.
 */
class RealTimeKernelContext(private val wallClock: Clock = Clock.systemUTC()) : KernelContext {
    private val log = LoggerFactory.getLogger(RealTimeKernelContext::class.java)
    private val startNanos = System.nanoTime()
    private val queue = ConcurrentLinkedQueue<() -> Unit>()
    private val pending = AtomicInteger()

    @Volatile
    private var runner: Thread? = null

    @Volatile
    private var kernelThread: Thread? = null

    // Runs the queue and the delayed tasks' timers; a timer that fires queues its task like any caller. Its priority
    // is the highest, which the JVM applies only with -XX:ThreadPriorityPolicy=1 as root (not a default: README,
    // "Session 25").
    private val executor: ScheduledExecutorService = Executors.newSingleThreadScheduledExecutor { runnable ->
        Thread(runnable, "kernel").also {
            it.priority = Thread.MAX_PRIORITY
            it.isDaemon = true
            kernelThread = it
        }
    }

    override fun now(): Instant = wallClock.instant()

    override fun elapsedMillis(): Long = (System.nanoTime() - startNanos) / 1_000_000

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable {
        if (delayMillis <= 0) {
            val cancelled = AtomicBoolean()
            enqueueQuietly { if (!cancelled.get()) action() }
            return Cancellable { cancelled.set(true) }
        }
        val future = try {
            executor.schedule({ enqueueQuietly(action) }, delayMillis, TimeUnit.MILLISECONDS)
        } catch (closing: RejectedExecutionException) {
            droppedWhileClosing()
            return Cancellable {}
        }
        return Cancellable { future.cancel(false) }
    }

    override fun execute(task: () -> Unit) {
        enqueueQuietly(task)
    }

    override fun submit(task: () -> Unit) {
        enqueue(task) // throws RejectedExecutionException once closed, as call does
    }

    override suspend fun <T> call(block: () -> T): T {
        if (isInKernelContext()) return block()
        var outcome: Result<T>? = null
        if (runHereIfIdle { outcome = runCatching(block) }) return checkNotNull(outcome).getOrThrow()
        val result = CompletableDeferred<T>()
        enqueue { runCatching(block).fold(result::complete, result::completeExceptionally) }
        return result.await()
    }

    override fun runHereIfIdle(task: () -> Unit): Boolean {
        if (executor.isShutdown || !pending.compareAndSet(0, 1)) return false
        runner = Thread.currentThread()
        try {
            runGuarded(task)
        } finally {
            runner = null
            // Tasks queued meanwhile wait for this thread; the kernel thread runs them, not the caller's.
            if (pending.decrementAndGet() > 0) startKernelThread()
        }
        return true
    }

    override fun isInKernelContext(): Boolean = Thread.currentThread() === runner

    override fun close() {
        executor.shutdownNow()
        executor.awaitTermination(5, TimeUnit.SECONDS)
    }

    private fun enqueue(task: () -> Unit) {
        if (executor.isShutdown) throw RejectedExecutionException("the kernel context is closed")
        queue.add(task)
        if (pending.getAndIncrement() == 0) {
            if (Thread.currentThread() === kernelThread) runQueue() else startKernelThread()
        }
    }

    // The last tasks of a stopping kernel (a driver reporting while it is disabled) may still schedule more; nothing
    // will run them, and that is fine.
    private fun enqueueQuietly(task: () -> Unit): Boolean = try {
        enqueue(task)
        true
    } catch (closing: RejectedExecutionException) {
        droppedWhileClosing()
        false
    }

    private fun startKernelThread() {
        try {
            executor.execute(::runQueue)
        } catch (closing: RejectedExecutionException) {
            droppedWhileClosing()
        }
    }

    /** Runs queued tasks until none is left; only the thread that holds [pending] calls it. */
    private fun runQueue() {
        do {
            runner = Thread.currentThread()
            runGuarded(checkNotNull(queue.poll()) { "a task was counted but not queued" })
            runner = null
        } while (pending.decrementAndGet() > 0)
    }

    private fun droppedWhileClosing() = log.debug("task scheduled while the kernel context closes; dropped")

    // A task that throws must not take the kernel thread down with it; the error is a bug to log, not to propagate.
    private fun runGuarded(action: () -> Unit) {
        try {
            action()
        } catch (error: Exception) {
            log.error("kernel task failed", error)
        }
    }
}
