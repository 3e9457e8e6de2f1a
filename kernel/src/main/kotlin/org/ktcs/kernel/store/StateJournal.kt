package org.ktcs.kernel.store

import org.slf4j.LoggerFactory
import java.util.PriorityQueue
import java.util.concurrent.locks.ReentrantLock
import kotlin.concurrent.thread
import kotlin.concurrent.withLock

/**
 * The ordered journal of kernel changes and the two threads that put it on the disk. The kernel thread only [append]s
 * (a map insertion under a lock the writer holds for a swap); the writer takes everything appended since its last
 * commit, keeps the newest change per row, and writes it in one transaction (a group commit), so that the store keeps
 * up however fast the kernel changes. A failing write is retried; until it succeeds nothing is reported committed.
 *
 * A commit is not flushed by the writer: the flusher puts it on the disk (an fsync), and only when a client waits for
 * it ([mark], `persistence.durability=COMMIT`). While one flush runs, the writer already commits the next group, and
 * the next flush puts all that was committed meanwhile on the disk at once: an fsync's time is not added to that of
 * the commits, and under load one fsync answers every request that came while the last one ran. The kernel's own
 * changes (a vehicle reached a point, an order was assigned) become durable with the next flush. A write-ahead log is
 * replayed in order, so a power cut loses at most the unflushed commits at its end, never a change a client was told
 * is committed; `kill -9` loses none of them. A flush that fails has the commits it should have flushed written again
 * (the operating system may have dropped them) before it is tried again. A store whose commit is on the disk once it
 * returns (PostgreSQL) has no flusher: the writer answers the requests it committed itself.
 *
 * A group commit gathers what is on its way: a client's [mark] wakes the writer through [later] (the kernel context's
 * queue), that is after the requests already queued in the kernel made their changes and marked them too; with one
 * client that costs a task switch, not a wait. With [groupNanos] > 0 (`persistence.groupWait`, for a slow disk) the
 * writer also waits for the requests it expects back (see [expected]): the clients it just answered and those already
 * waiting send their next request; never longer than [groupNanos] after the last flush.
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
    private val flushable = lock.newCondition()
    private var pending = LinkedHashMap<Pair<StoreTable, String>, StoreChange>()
    private var appended = 0L
    private var flushRequested = 0L
    private var committed = 0L
    private var flushed = 0L

    // The commits not yet flushed, oldest first, each with the count of changes appended up to it: a failed flush has
    // them written again (rewriteUnflushed) before it is retried.
    private val unflushed = ArrayDeque<Pair<Long, Collection<StoreChange>>>()
    private var rewriteUnflushed = false

    @Volatile
    private var running = true
    private var writerStopped = false
    private var wakeQueued = false

    // The requests the next commit waits for: those the last flush answered plus those that marked while it ran
    // (each sends its next request once answered); 1 with one client, so that it never waits.
    private var expected = 1
    private var marked = 0
    private var groupDeadline = System.nanoTime()
    private val waiting = PriorityQueue<Waiter>(compareBy { it.mark })
    private var notificationsWritten = 0L
    private val counts = Counts()

    // A store whose commits are on the disk already (PostgreSQL): the writer answers, without a hand-off to a flusher.
    private val answerWhenCommitted = waitForCommit && store.commitsFlushed
    private val writer = thread(name = "state-store-writer", isDaemon = true) { writeLoop() }
    private val flusher = if (waitForCommit && !answerWhenCommitted) {
        thread(name = "state-store-flusher", isDaemon = true) {
            flushLoop()
        }
    } else {
        null
    }

    fun append(change: StoreChange) {
        lock.withLock {
            pending.putNewest(change)
            appended++
            // With COMMIT the writer looks for the kernel's own changes every few milliseconds (a client's mark wakes
            // it): one commit for a request's changes and the kernel's around it, and no wake-up per change.
            if (!waitForCommit) changed.signal()
        }
    }

    override fun mark(): Long {
        if (!waitForCommit) return 0
        var wake = false
        val mark = lock.withLock {
            if (appended > flushRequested) flushRequested = appended
            if (flushRequested > committed) {
                marked++
                // The group's last mark wakes the writer (before its deadline the writer waits for no fewer).
                wake = !wakeQueued && groupComplete()
                if (wake) wakeQueued = true
            } else if (flushDue()) {
                flushable.signal() // committed already (the kernel's own changes), only to be flushed
            }
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

    /** Whether a flush would answer a waiting request: a requested mark is committed but not on the disk. */
    private fun flushDue() = !rewriteUnflushed && minOf(flushRequested, committed) > flushed

    /** Writes and flushes what is pending and stops (waiting at most 15 s for a store that cannot be written). */
    override fun close() {
        lock.withLock {
            running = false
            changed.signal()
        }
        writer.join(CLOSE_TIMEOUT_MILLIS)
        lock.withLock {
            writerStopped = true
            flushable.signal()
        }
        flusher?.join(CLOSE_TIMEOUT_MILLIS)
        store.close()
        log.info("state store writer: {}", counts)
    }

    private fun writeLoop() {
        while (true) {
            val (batch, upTo) = lock.withLock {
                awaitWork()
                if (!running && pending.isEmpty() && !rewriteUnflushed) return
                takeBatch()
            }
            val written = batch.isEmpty() || writeUntilDone(batch)
            lock.withLock {
                // Stopping with a store that cannot be written: nothing of this batch or after it is answered.
                if (!written) return
                committed = upTo
                if (waitForCommit && !answerWhenCommitted) {
                    unflushed.addLast(upTo to batch)
                    if (flushDue()) flushable.signal()
                }
            }
            if (answerWhenCommitted) answer(upTo)
        }
    }

    /** Takes what is pending (after what a failed flush left unflushed, written again) as the next commit. */
    private fun takeBatch(): Pair<Collection<StoreChange>, Long> {
        val taken = if (rewriteUnflushed) {
            rewriteUnflushed = false
            LinkedHashMap<Pair<StoreTable, String>, StoreChange>().also { merged ->
                unflushed.forEach { (_, batch) -> batch.forEach { merged.putNewest(it) } }
                unflushed.clear()
                pending.values.forEach { merged.putNewest(it) }
            }
        } else {
            pending
        }
        pending = LinkedHashMap()
        marked = 0
        return taken.values to appended
    }

    /**
     * Waits, holding [lock], until there is a commit to make: with ASYNC any change; with COMMIT a complete group of
     * marks once the kernel woke the writer, or the kernel's own changes after [gatherNanos] (also a mark whose
     * wake-up did not come by then, e.g. from a stopping kernel); and commits a failed flush left to write again.
     */
    private fun awaitWork() {
        while (running && !rewriteUnflushed) {
            if (!waitForCommit) {
                if (pending.isNotEmpty()) return
                changed.await()
            } else if (flushRequested > committed) {
                // The group is complete once its last request marked (or its deadline passed); then the kernel's
                // wake-up, which comes after the requests queued behind that mark, starts the commit.
                val complete = groupComplete()
                if (complete && !wakeQueued) return
                val timedOut = changed.awaitNanos(if (complete) gatherNanos else groupDeadline - System.nanoTime())
                if (timedOut <= 0L && complete) return
            } else {
                // Until the group's deadline a mark signals only once the group is complete, so wait no longer; a
                // mark that came meanwhile waits for its group (the flusher sets the deadline as it answers).
                val untilGroup = groupDeadline - System.nanoTime()
                val timedOut = changed.awaitNanos(if (untilGroup > 0) untilGroup else gatherNanos) <= 0L
                if (timedOut && untilGroup <= 0 && pending.isNotEmpty() && flushRequested <= committed) return
            }
        }
    }

    /**
     * Flushes whenever a waiting request's commit is not yet on the disk, everything committed so far at once, and
     * answers the requests it put on the disk; stops once the writer stopped and nothing is left to flush.
     */
    private fun flushLoop() {
        var failures = 0
        while (true) {
            val upTo = lock.withLock {
                while (!flushDue()) {
                    if (writerStopped) return
                    flushable.await()
                }
                committed
            }
            try {
                store.flush()
            } catch (error: Exception) {
                if (failures++ == 0) {
                    log.error(
                        "state store flush failed; writing its commits again until a flush succeeds: {}",
                        error.message,
                    )
                }
                if (writerStopped && failures > CLOSE_RETRIES) return
                Thread.sleep(RETRY_MILLIS)
                lock.withLock {
                    rewriteUnflushed = true
                    changed.signal()
                }
                continue
            }
            if (failures > 0) log.warn("state store flushed again after {} failed attempt(s)", failures)
            failures = 0
            answer(upTo)
        }
    }

    /** Everything up to [upTo] is on the disk: the requests waiting for it are answered (outside the lock). */
    private fun answer(upTo: Long) {
        val answered = ArrayList<Waiter>()
        lock.withLock {
            flushed = upTo
            while (unflushed.firstOrNull()?.let { it.first <= upTo } == true) unflushed.removeFirst()
            while (waiting.peek()?.let { it.mark <= upTo } == true) answered += waiting.poll()
            expected = (answered.size + marked).coerceAtLeast(1)
            groupDeadline = System.nanoTime() + groupNanos
        }
        counts.flushed(answered.size)
        answered.forEach { it.committed() }
    }

    private class Waiter(val mark: Long, val committed: () -> Unit)

    /** How much the writer grouped: what a benchmark's log shows of the group commit. */
    private class Counts {
        private var commits = 0L
        private var changes = 0L

        @Volatile
        private var flushes = 0L

        @Volatile
        private var requests = 0L

        fun add(changes: Int) {
            commits++
            this.changes += changes
        }

        fun flushed(requests: Int) {
            flushes++
            this.requests += requests
        }

        override fun toString() =
            "$commits commits of $changes changes; $flushes flushes, answering $requests waiting requests " +
                "(%.1f per flush)".format(if (flushes == 0L) 0.0 else requests.toDouble() / flushes)
    }

    /** Writes [batch], retrying a failed write; false only if the journal stops before it could be written. */
    private fun writeUntilDone(batch: Collection<StoreChange>): Boolean {
        var failures = 0
        while (true) {
            try {
                store.write(batch)
                trimNotifications(batch)
                if (failures > 0) log.warn("state store writable again after {} failed attempt(s)", failures)
                counts.add(batch.size)
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

    /** Adds [change] as the newest of its row, in the order of the changes (a clear before later puts). */
    private fun MutableMap<Pair<StoreTable, String>, StoreChange>.putNewest(change: StoreChange) {
        val key = change.table to change.rowName
        if (change is StoreChange.Clear) keys.removeIf { it.first == change.table }
        remove(key)
        this[key] = change
    }

    companion object {
        const val NOTIFICATIONS_KEPT = 1000
        private const val GATHER_NANOS = 5_000_000L
        private const val GROUP_NANOS = 0L // persistence.groupWait's default
        private const val RETRY_MILLIS = 1_000L
        private const val CLOSE_RETRIES = 5
        private const val CLOSE_TIMEOUT_MILLIS = 15_000L
    }
}
