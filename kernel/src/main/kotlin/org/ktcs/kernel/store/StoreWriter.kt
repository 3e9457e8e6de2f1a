package org.ktcs.kernel.store

/** What the journal's writer thread needs of a store: [StateStore], or a test's stand-in. */
interface StoreWriter : AutoCloseable {
    /**
     * Writes [changes] in one transaction, in their order; with [flush] the commit returns only once it is on the
     * disk, without it a later flushed commit makes it durable.
     */
    fun write(changes: Collection<StoreChange>, flush: Boolean)

    /** Deletes the notifications older than the newest [keep] ([newest] is the newest one's number). */
    fun trimNotifications(newest: Long, keep: Int)
}
