package org.ktcs.kernel.store

import org.ktcs.kernel.core.KernelCore

/**
 * Lets a client's request wait until the changes it made are committed: [mark] in the kernel context after the
 * change, [awaitCommitted] outside it. Without a store (or with `persistence.durability=ASYNC`) nothing waits.
 */
interface CommitBarrier {
    /** The position of the newest change so far; call in the kernel context. */
    fun mark(): Long

    /** Suspends until every change up to [mark] is committed. */
    suspend fun awaitCommitted(mark: Long)

    companion object {
        val NONE: CommitBarrier = object : CommitBarrier {
            override fun mark(): Long = 0

            override suspend fun awaitCommitted(mark: Long) = Unit
        }
    }
}

/**
 * Runs [block] in the kernel context and returns its result once the changes it made are committed to the store
 * (`persistence.durability=COMMIT`), so that an answered request survives a crash.
 */
suspend fun <T> KernelCore.durably(block: () -> T): T {
    var mark = 0L
    val result = context.call { block().also { mark = commits.mark() } }
    commits.awaitCommitted(mark)
    return result
}
