package org.ktcs.kernel.store

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.suspendCancellableCoroutine
import org.ktcs.kernel.core.KernelCore
import kotlin.coroutines.resume

/**
 * Lets a client's request wait until the changes it made are committed: [mark] in the kernel context after the
 * change, then [whenCommitted]. Without a store (or with `persistence.durability=ASYNC`) nothing waits.
 */
interface CommitBarrier {
    /** The position of the newest change so far; call in the kernel context. */
    fun mark(): Long

    /**
     * Calls [committed] once every change up to [mark] is committed: at once if they are, else on the thread that
     * committed them, which it must not hold up (complete a deferred value, resume a coroutine).
     */
    fun whenCommitted(mark: Long, committed: () -> Unit)

    /** Whether a request may wait for its commit (`COMMIT`); without waits, the kernel's answer is the request's. */
    val waits: Boolean get() = true

    companion object {
        val NONE: CommitBarrier = object : CommitBarrier {
            override val waits = false

            override fun mark(): Long = 0

            override fun whenCommitted(mark: Long, committed: () -> Unit) = committed()
        }
    }
}

/** Suspends until every change up to [mark] is committed. */
suspend fun CommitBarrier.awaitCommitted(mark: Long) = suspendCancellableCoroutine { waiting ->
    whenCommitted(mark) { waiting.resume(Unit) }
}

/**
 * Runs [block] in the kernel context and returns its result once the changes it made are committed to the store
 * (`persistence.durability=COMMIT`), so that an answered request survives a crash. The caller is resumed once, by
 * the thread that committed: not first by the kernel thread and then again by the writer (and not at all when
 * the calling thread ran [block] itself and nothing waits for a commit).
 */
suspend fun <T> KernelCore.durably(block: () -> T): T {
    if (context.isInKernelContext()) {
        return block().also { commits.awaitCommitted(commits.mark()) }
    }
    val answer = CompletableDeferred<T>()
    val task: () -> Unit = {
        runCatching(block).fold(
            { result -> commits.whenCommitted(commits.mark()) { answer.complete(result) } },
            answer::completeExceptionally,
        )
    }
    // A request waiting for its commit stays on the kernel thread, where the writer's wake-up queued after it follows
    // at once (run here, that wake-up would cost a wake of the kernel thread of its own, measured slower).
    if (commits.waits || !context.runHereIfIdle(task)) context.submit(task)
    return answer.await()
}
