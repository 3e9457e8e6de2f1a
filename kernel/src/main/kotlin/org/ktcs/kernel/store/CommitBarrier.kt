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

    companion object {
        val NONE: CommitBarrier = object : CommitBarrier {
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
 * the thread that committed: not first by the kernel thread and then again by the writer.
 */
suspend fun <T> KernelCore.durably(block: () -> T): T {
    if (context.isInKernelContext()) {
        return block().also { commits.awaitCommitted(commits.mark()) }
    }
    val answer = CompletableDeferred<T>()
    context.submit {
        runCatching(block).fold(
            { result -> commits.whenCommitted(commits.mark()) { answer.complete(result) } },
            answer::completeExceptionally,
        )
    }
    return answer.await()
}
