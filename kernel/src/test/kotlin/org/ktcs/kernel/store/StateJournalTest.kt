package org.ktcs.kernel.store

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import java.util.concurrent.TimeUnit

/**
 * The journal flushes (fsyncs) exactly the commits a client waits for: the kernel's own changes are committed
 * without, and a client's change the writer had already committed unflushed is flushed once the client marks it.
 */
class StateJournalTest : FunSpec({
    fun put(name: String) = StoreChange.Put(StoreTable.PLANT_LOCKS, name, StoredLock(StoredLock.PATH, true))

    test("the kernel's own changes are committed without a flush, a client's change with one") {
        val store = RecordingStore()
        StateJournal(store, waitForCommit = true).use { journal ->
            journal.append(put("kernel-change"))
            store.awaitWrites(1)
            journal.append(put("client-change"))
            val mark = journal.mark()
            runBlocking { withTimeout(5_000) { journal.awaitCommitted(mark) } }

            store.writes.first() shouldBe (listOf("kernel-change") to false)
            // The client's change went in a flushed commit, or in one before the flushed one that followed its mark.
            store.writes.flatMap { it.first } shouldContain "client-change"
            store.writes.last().second shouldBe true
        }
    }

    test("a client's change the writer committed unflushed before the client marked it is flushed after the mark") {
        val store = RecordingStore()
        StateJournal(store, waitForCommit = true).use { journal ->
            journal.append(put("client-change"))
            store.awaitWrites(1)
            val mark = journal.mark()
            runBlocking { withTimeout(5_000) { journal.awaitCommitted(mark) } }

            store.writes.map { it.second } shouldContainExactly listOf(false, true)
            store.writes.last().first shouldBe listOf("lastFlush")
        }
    }

    test("with ASYNC durability nothing is flushed and nothing waits") {
        val store = RecordingStore()
        StateJournal(store, waitForCommit = false).use { journal ->
            journal.append(put("client-change"))
            journal.mark() shouldBe 0
            store.awaitWrites(1)
            store.writes.single().second shouldBe false
        }
    }
})

/** Records each write's row names and whether it was flushed. */
private class RecordingStore : StoreWriter {
    val writes: MutableList<Pair<List<String>, Boolean>> = java.util.Collections.synchronizedList(mutableListOf())
    private val counted = java.util.concurrent.Semaphore(0)

    override fun write(changes: Collection<StoreChange>, flush: Boolean) {
        writes += changes.map { it.rowName } to flush
        counted.release()
    }

    override fun trimNotifications(newest: Long, keep: Int) = Unit

    override fun close() = Unit

    fun awaitWrites(count: Int) {
        check(counted.tryAcquire(count, 5, TimeUnit.SECONDS)) { "fewer than $count writes" }
        counted.release(count)
    }
}
