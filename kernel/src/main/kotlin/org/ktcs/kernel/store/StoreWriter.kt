package org.ktcs.kernel.store

/** What the journal's threads need of a store: [StateStore], or a test's stand-in. */
interface StoreWriter : AutoCloseable {
    /**
     * Writes [changes] in one transaction, in their order; once it returns the commit survives `kill -9`, and a later
     * [flush] puts it on the disk.
     */
    fun write(changes: Collection<StoreChange>)

    /**
     * Puts every commit [write] returned from on the disk (survives a power cut). Runs on its own thread, possibly
     * while [write] runs, never two at once.
     */
    fun flush()

    /** Whether a commit is on the disk once [write] returns (PostgreSQL, as its server is configured): no [flush]. */
    val commitsFlushed: Boolean get() = false

    /** Deletes the notifications older than the newest [keep] ([newest] is the newest one's number). */
    fun trimNotifications(newest: Long, keep: Int)
}
