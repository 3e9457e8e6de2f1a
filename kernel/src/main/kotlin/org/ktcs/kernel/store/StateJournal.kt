package org.ktcs.kernel.store

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import org.slf4j.LoggerFactory
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
 */
class StateJournal(private val store: StoreWriter, private val waitForCommit: Boolean) : CommitBarrier, AutoCloseable {
    private val log = LoggerFactory.getLogger(StateJournal::class.java)
    private val lock = ReentrantLock()
    private val changed = lock.newCondition()
    private var pending = LinkedHashMap<Pair<StoreTable, String>, StoreChange>()
    private var appended = 0L
    private var flushRequested = 0L
    private var flushed = 0L
    private var running = true
    private val durable = MutableStateFlow(0L)
    private var notificationsWritten = 0L
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
            // With COMMIT the writer gathers the kernel's own changes for a moment (a client's mark ends that at once):
            // one commit for a request's changes and the kernel's around it, not one per change.
            if (pending.size == 1 || !waitForCommit) changed.signal()
        }
    }

    override fun mark(): Long = if (waitForCommit) {
        lock.withLock {
            if (appended > flushRequested) {
                flushRequested = appended
                changed.signal()
            }
            appended
        }
    } else {
        0
    }

    override suspend fun awaitCommitted(mark: Long) {
        if (durable.value < mark) durable.first { it >= mark }
    }

    /** Writes what is pending and stops the writer (waiting at most 15 s for a store that cannot be written). */
    override fun close() {
        lock.withLock {
            running = false
            changed.signal()
        }
        writer.join(CLOSE_TIMEOUT_MILLIS)
        store.close()
    }

    private fun writeLoop() {
        while (true) {
            val (batch, upTo, flush) = lock.withLock {
                while (running && flushRequested <= flushed) {
                    if (pending.isEmpty()) {
                        changed.await()
                    } else if (!waitForCommit || changed.awaitNanos(GATHER_NANOS) <= 0L) {
                        break
                    }
                }
                if (pending.isEmpty() && flushRequested <= flushed) return
                val taken = pending
                pending = LinkedHashMap()
                Triple(taken.values, appended, flushRequested > flushed)
            }
            // A client waits for changes the writer took (unflushed) before the client's request marked them.
            writeUntilDone(batch.ifEmpty { listOf(flushMarker()) }, flush)
            if (flush) {
                flushed = upTo
                durable.value = upTo
            }
        }
    }

    private fun flushMarker() = StoreChange.Put(StoreTable.KERNEL_VALUES, FLUSHED_KEY, System.currentTimeMillis())

    private fun writeUntilDone(batch: Collection<StoreChange>, flush: Boolean) {
        var failures = 0
        while (true) {
            try {
                store.write(batch, flush)
                trimNotifications(batch)
                if (failures > 0) log.warn("state store writable again after {} failed attempt(s)", failures)
                return
            } catch (error: Exception) {
                if (failures++ == 0) {
                    log.error(
                        "state store write failed; retrying until it succeeds: {}",
                        error.message,
                    )
                }
                if (!running && failures > CLOSE_RETRIES) {
                    log.error("state store: {} change(s) not written at shutdown", batch.size)
                    return
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
        private const val RETRY_MILLIS = 1_000L
        private const val CLOSE_RETRIES = 5
        private const val CLOSE_TIMEOUT_MILLIS = 15_000L
    }
}
