package org.ktcs.kernel.context

import kotlinx.coroutines.CompletableDeferred
import org.ktcs.api.kernel.Cancellable
import org.slf4j.LoggerFactory
import java.time.Clock
import java.time.Instant
import java.util.concurrent.Executors
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.TimeUnit

/** The kernel context on the wall clock: one thread named `kernel` runs every task. */
class RealTimeKernelContext(private val wallClock: Clock = Clock.systemUTC()) : KernelContext {
    private val log = LoggerFactory.getLogger(RealTimeKernelContext::class.java)
    private val startNanos = System.nanoTime()

    @Volatile
    private var kernelThread: Thread? = null

    private val executor: ScheduledExecutorService = Executors.newSingleThreadScheduledExecutor { runnable ->
        Thread(runnable, "kernel").also {
            it.isDaemon = true
            kernelThread = it
        }
    }

    override fun now(): Instant = wallClock.instant()

    override fun elapsedMillis(): Long = (System.nanoTime() - startNanos) / 1_000_000

    override fun schedule(delayMillis: Long, action: () -> Unit): Cancellable {
        val future = try {
            executor.schedule({ runGuarded(action) }, delayMillis.coerceAtLeast(0), TimeUnit.MILLISECONDS)
        } catch (closing: RejectedExecutionException) {
            // The last tasks of a stopping kernel (a driver reporting while it is disabled) may still schedule more;
            // nothing will run them, and that is fine.
            log.debug("task scheduled while the kernel context closes; dropped")
            return Cancellable {}
        }
        return Cancellable { future.cancel(false) }
    }

    override fun submit(task: () -> Unit) {
        executor.execute { runGuarded(task) } // throws RejectedExecutionException once closed, as call does
    }

    override suspend fun <T> call(block: () -> T): T {
        if (isInKernelContext()) return block()
        val result = CompletableDeferred<T>()
        executor.execute { runCatching(block).fold(result::complete, result::completeExceptionally) }
        return result.await()
    }

    override fun isInKernelContext(): Boolean = Thread.currentThread() === kernelThread

    override fun close() {
        executor.shutdownNow()
        executor.awaitTermination(5, TimeUnit.SECONDS)
    }

    // A task that throws must not take the kernel thread down with it; the error is a bug to log, not to propagate.
    private fun runGuarded(action: () -> Unit) {
        try {
            action()
        } catch (error: Exception) {
            log.error("kernel task failed", error)
        }
    }
}
