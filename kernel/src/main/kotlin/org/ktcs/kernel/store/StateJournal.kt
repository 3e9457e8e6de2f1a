package org.ktcs.kernel.store

import org.slf4j.LoggerFactory
import java.util.PriorityQueue
import java.util.concurrent.locks.ReentrantLock
import kotlin.concurrent.thread
import kotlin.concurrent.withLock

/**
 * The ordered journal of kernel changes and the thread that writes it. The kernel thread only [append]s (a map
 * insertion under a lock the writer holds for a swap); the writer takes everything appended since its last commit,
 * keeps the newest change per row, and writes it in one transaction (a group commit), so that the store keeps up
 * however fast the kernel changes. A failing write is retried; until it succeeds nothing is reported committed.
 *
 * Only a commit that a client waits for ([mark], `persistence.durability=COMMIT`) is flushed to the disk (an fsync);
 * the kernel's own changes (a vehicle reached a point, an order was assigned) are committed without, and become
 * durable with the next flushed commit. A write-ahead log is replayed in order, so a power cut loses at most those
 * unflushed commits at its end, never a change a client was told is committed; `kill -9` loses none of them.
 *
 * A group commit gathers what is on its way: a client's [mark] wakes the writer through [later] (the kernel context's
 * queue), that is after the requests already queued in the kernel made their changes and marked them too, so that
 * one fsync answers all of them; with one client that costs a task switch, not a wait. With [groupNanos] > 0
 * (`persistence.groupWait`, for a slow disk) the writer also waits for the requests it expects back (see
 * [expected]): the clients it just answered and those already waiting send their next request, and one flushed
 * commit for all of them costs one fsync and one wake-up of each of the web server's threads instead of one per few
 * requests; never longer than [groupNanos] after its last flushed commit.
 */
class StateJournal(
    private val store: StoreWriter,
    private val waitForCommit: Boolean,
    private val gatherNanos: Long = GATHER_NANOS,
    private val groupNanos: Long = GROUP_NANOS,
    private val later: (() -> Unit) -> Unit = { it() },
) : CommitBarrier, AutoCloseable {
    private val log = LoggerFactory.getLogger(StateJournal::class.java)
    private val lock = ReentrantLock()
    private val changed = lock.newCondition()
    private var pending = LinkedHashMap<Pair<StoreTable, String>, StoreChange>()
    private var appended = 0L
    private var flushRequested = 0L
    private var flushed = 0L
    private var running = true
    private var wakeQueued = false

    // The requests the next flushed commit waits for: those the last one answered plus those that marked while it
    // was written (each sends its next request once answered); 1 with one client, so that it never waits.
    private var expected = 1
    private var marked = 0
    private var groupDeadline = System.nanoTime()
    private val waiting = PriorityQueue<Waiter>(compareBy { it.mark })
    private var notificationsWritten = 0L
    private val counts = Counts()
    private val writer = thread(name = "state-store-writer", isDaemon = true) { writeLoop() }

    fun append(change: StoreChange) {
        lock.withLock {
            val key = change.table to change.rowName
            if (change is StoreChange.Clear) {
                pending.keys.removeIf { it.first == change.table }
            }
            // Re-inserted so that the map's order stays the order of the changes (a clear before later puts).
            pending.remove(key)
            pending[key] = change
            appended++
            // With COMMIT the writer looks for the kernel's own changes every few milliseconds (a client's mark wakes
            // it): one commit for a request's changes and the kernel's around it, and no wake-up per change.
            if (!waitForCommit) changed.signal()
        }
    }

    override val waits: Boolean get() = waitForCommit

    override fun mark(): Long {
        if (!waitForCommit) return 0
        var wake = false
        val mark = lock.withLock {
            if (appended > flushRequested) flushRequested = appended
            if (flushRequested > flushed) marked++
            // The group's last mark wakes the writer (before its deadline the writer waits for no fewer).
            wake = flushRequested > flushed && !wakeQueued && groupComplete()
            if (wake) wakeQueued = true
            appended
        }
        if (wake) later(::wakeWriter)
        return mark
    }

    override fun whenCommitted(mark: Long, committed: () -> Unit) {
        val now = lock.withLock { (flushed >= mark).also { if (!it) waiting += Waiter(mark, committed) } }
        if (now) committed()
    }

    private fun wakeWriter() = lock.withLock {
        wakeQueued = false
        changed.signal()
    }

    /** Whether the group the writer waits for is complete: as many marks as expected, or its deadline passed. */
    private fun groupComplete() = marked >= expected || System.nanoTime() - groupDeadline >= 0

    /** Writes what is pending and stops the writer (waiting at most 15 s for a store that cannot be written). */
    override fun close() {
        lock.withLock {
            running = false
            changed.signal()
        }
        writer.join(CLOSE_TIMEOUT_MILLIS)
        store.close()
        log.info("state store writer: {}", counts)
    }

    private fun writeLoop() {
        while (true) {
            val (batch, upTo, flush) = lock.withLock {
                awaitWork()
                if (pending.isEmpty() && flushRequested <= flushed) return
                val taken = pending
                pending = LinkedHashMap()
                marked = 0
                Triple(taken.values, appended, flushRequested > flushed)
            }
            // A client waits for changes the writer took (unflushed) before the client's request marked them.
            // Stopping with a store that cannot be written: nothing of this batch or after it is answered as committed.
            val started = System.nanoTime()
            if (!writeUntilDone(batch.ifEmpty { listOf(flushMarker()) }, flush)) return
            val written = System.nanoTime()
            counts.add(batch.size, flush, written - started)
            if (flush) answer(upTo)
            counts.answerNanos += System.nanoTime() - written
        }
    }

    /**
     * Waits, holding [lock], until there is a commit to make: with ASYNC any change; with COMMIT a complete group of
     * marks once the kernel woke the writer, or the kernel's own changes after [gatherNanos] (also a mark whose
     * wake-up did not come by then, e.g. from a stopping kernel).
     */
    private fun awaitWork() {
        while (running) {
            if (!waitForCommit) {
                if (pending.isNotEmpty()) return
                changed.await()
            } else if (flushRequested > flushed) {
                // The group is complete once its last request marked (or its deadline passed); then the kernel's
                // wake-up, which comes after the requests queued behind that mark, starts the commit.
                val complete = groupComplete()
                if (complete && !wakeQueued) return
                val timedOut = changed.awaitNanos(if (complete) gatherNanos else groupDeadline - System.nanoTime())
                if (timedOut <= 0L && complete) return
            } else {
                // Until the group's deadline a mark signals only once the group is complete, so wait no longer.
                val untilGroup = groupDeadline - System.nanoTime()
                val timedOut = changed.awaitNanos(if (untilGroup > 0) untilGroup else gatherNanos) <= 0L
                if (timedOut && untilGroup <= 0 && pending.isNotEmpty()) return
            }
        }
    }

    /** Everything up to [upTo] is on the disk: the requests waiting for it are answered (outside the lock). */
    private fun answer(upTo: Long) {
        val answered = ArrayList<Waiter>()
        lock.withLock {
            flushed = upTo
            while (waiting.peek()?.let { it.mark <= upTo } == true) answered += waiting.poll()
            expected = (answered.size + marked).coerceAtLeast(1)
            groupDeadline = System.nanoTime() + groupNanos
        }
        counts.requests += answered.size
        answered.forEach { it.committed() }
    }

    private class Waiter(val mark: Long, val committed: () -> Unit)

    /**
     * How much the writer grouped and how busy it was: what a benchmark's log shows of the group commit. A writer
     * writing most of the time is what limits `COMMIT`'s rate; one mostly waiting is held up by the hand-offs.
     */
    private class Counts {
        private val startNanos = System.nanoTime()
        private var commits = 0L
        private var flushedCommits = 0L
        private var changes = 0L
        private var writeNanos = 0L
        var requests = 0L
        var answerNanos = 0L

        fun add(changes: Int, flushed: Boolean, nanos: Long) {
            commits++
            if (flushed) flushedCommits++
            this.changes += changes
            writeNanos += nanos
        }

        override fun toString() =
            "$commits commits of $changes changes; $flushedCommits flushed, answering $requests waiting requests " +
                "(%.1f per flushed commit); writing %.2f s and answering %.2f s of %.1f s".format(
                    if (flushedCommits == 0L) 0.0 else requests.toDouble() / flushedCommits,
                    writeNanos / NANOS_PER_SECOND,
                    answerNanos / NANOS_PER_SECOND,
                    (System.nanoTime() - startNanos) / NANOS_PER_SECOND,
                )
    }

    private fun flushMarker() = StoreChange.Put(StoreTable.KERNEL_VALUES, FLUSHED_KEY, System.currentTimeMillis())

    /** Writes [batch], retrying a failed write; false only if the journal stops before it could be written. */
    private fun writeUntilDone(batch: Collection<StoreChange>, flush: Boolean): Boolean {
        var failures = 0
        while (true) {
            try {
                store.write(batch, flush)
                trimNotifications(batch)
                if (failures > 0) log.warn("state store writable again after {} failed attempt(s)", failures)
                return true
            } catch (error: Exception) {
                if (failures++ == 0) {
                    log.error(
                        "state store write failed; retrying until it succeeds: {}",
                        error.message,
                    )
                }
                if (!running && failures > CLOSE_RETRIES) {
                    log.error("state store: {} change(s) not written at shutdown", batch.size)
                    return false
                }
                Thread.sleep(RETRY_MILLIS)
            }
        }
    }

    private fun trimNotifications(batch: Collection<StoreChange>) {
        val newest = batch.filterIsInstance<StoreChange.Put>().filter { it.table == StoreTable.NOTIFICATIONS }
            .maxOfOrNull { it.name.toLong() } ?: return
        notificationsWritten += batch.count { it.table == StoreTable.NOTIFICATIONS }
        if (notificationsWritten < NOTIFICATIONS_KEPT / 10) return
        notificationsWritten = 0
        store.trimNotifications(newest, NOTIFICATIONS_KEPT)
    }

    companion object {
        const val NOTIFICATIONS_KEPT = 1000
        private const val FLUSHED_KEY = "lastFlush"
        private const val GATHER_NANOS = 5_000_000L
        private const val NANOS_PER_SECOND = 1e9
        private const val GROUP_NANOS = 0L // persistence.groupWait's default
        private const val RETRY_MILLIS = 1_000L
        private const val CLOSE_RETRIES = 5
        private const val CLOSE_TIMEOUT_MILLIS = 15_000L
    }
}
