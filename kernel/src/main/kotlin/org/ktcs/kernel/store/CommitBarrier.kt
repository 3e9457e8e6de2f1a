package org.ktcs.kernel.store

import io.netty.util.internal.ThreadExecutorMap
import kotlinx.coroutines.suspendCancellableCoroutine
import org.ktcs.kernel.core.KernelCore
import java.util.concurrent.Executor
import kotlin.coroutines.resume
import kotlin.coroutines.resumeWithException

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

    /**
     * As [whenCommitted], for a caller that is answered on [answerOn] (its connection's event loop): a barrier may
     * answer every caller of one loop in one task there, instead of handing each its own.
     */
    fun whenCommitted(mark: Long, answerOn: Executor?, committed: () -> Unit) = whenCommitted(mark, committed)

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
 * the thread that committed: not first by the kernel thread and then again by the writer; a caller on a web server's
 * event loop is resumed there together with the other callers of that loop the same commit answers.
 */
suspend fun <T> KernelCore.durably(block: () -> T): T {
    if (context.isInKernelContext()) {
        return block().also { commits.awaitCommitted(commits.mark()) }
    }
    val loop = currentEventLoop()
    return suspendCancellableCoroutine { waiting ->
        context.submit {
            runCatching(block).fold(
                { result -> commits.whenCommitted(commits.mark(), loop) { waiting.resume(result) } },
                waiting::resumeWithException,
            )
        }
    }
}

/**
 * The Netty event loop the calling thread runs (a web request's connection), or `null` on any other thread. Netty's
 * own lookup (public, though in its `internal` package; there since 4.1.43): Ktor keeps the loop in an internal
 * class of its coroutine context.
 */
private fun currentEventLoop(): Executor? = ThreadExecutorMap.currentExecutor()
