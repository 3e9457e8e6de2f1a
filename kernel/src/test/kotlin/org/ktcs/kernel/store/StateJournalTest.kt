package org.ktcs.kernel.store

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.longs.shouldBeLessThan
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

    test("requests marked before the kernel wakes the writer share one flushed commit (a group commit)") {
        val store = RecordingStore()
        val wakes = java.util.concurrent.LinkedBlockingQueue<() -> Unit>()
        // A gather longer than the test: only the wake-up can start the flushed commit.
        StateJournal(store, waitForCommit = true, gatherNanos = 60_000_000_000L, later = wakes::add).use { journal ->
            val answered = java.util.concurrent.CountDownLatch(8)
            repeat(8) { request ->
                journal.append(put("order-$request"))
                journal.whenCommitted(journal.mark()) { answered.countDown() }
            }
            Thread.sleep(100)

            answered.count shouldBe 8
            store.writes shouldBe emptyList()
            wakes.size shouldBe 1
            wakes.poll()()
            answered.await(5, TimeUnit.SECONDS) shouldBe true
            store.writes.single() shouldBe ((0 until 8).map { "order-$it" } to true)
        }
    }

    test("under load the next flushed commit waits for as many requests as the last one answered, then answers all") {
        val store = RecordingStore()
        val wakes = java.util.concurrent.LinkedBlockingQueue<() -> Unit>()
        val onDisk = java.util.concurrent.Semaphore(0)
        store.beforeWrite = { onDisk.acquire() }
        // Gather and group deadline longer than the test: only a complete group can start a flushed commit.
        StateJournal(store, true, gatherNanos = 60_000_000_000L, groupNanos = 60_000_000_000L, later = wakes::add)
            .use { journal ->
                // Requests queued in the kernel mark one after the other; then the kernel runs the wake-ups.
                fun requests(names: List<String>, answered: java.util.concurrent.CountDownLatch) {
                    names.forEach { name ->
                        journal.append(put(name))
                        journal.whenCommitted(journal.mark()) { answered.countDown() }
                    }
                    generateSequence { wakes.poll() }.forEach { it() }
                }
                val first = java.util.concurrent.CountDownLatch(3)
                requests((1..3).map { "first-$it" }, first)
                Thread.sleep(100)
                first.count shouldBe 3 // the group is not answered before its commit is on the disk
                onDisk.release(10)
                first.await(5, TimeUnit.SECONDS) shouldBe true

                val second = java.util.concurrent.CountDownLatch(3)
                requests((1..2).map { "second-$it" }, second)
                Thread.sleep(100)
                second.count shouldBe 3
                store.writes.size shouldBe 1
                requests(listOf("second-3"), second)
                second.await(5, TimeUnit.SECONDS) shouldBe true
                store.writes shouldBe listOf(
                    (1..3).map { "first-$it" } to true,
                    (1..3).map { "second-$it" } to true,
                )
            }
    }

    test("a group that does not complete is committed at its deadline; one client never waits for a group") {
        val store = RecordingStore()
        val wakes = java.util.concurrent.LinkedBlockingQueue<() -> Unit>()
        StateJournal(store, true, groupNanos = 200_000_000L, later = wakes::add).use { journal ->
            fun request(name: String): java.util.concurrent.CountDownLatch {
                val answered = java.util.concurrent.CountDownLatch(1)
                journal.append(put(name))
                journal.whenCommitted(journal.mark()) { answered.countDown() }
                return answered
            }
            fun wake() = generateSequence { wakes.poll() }.forEach { it() }
            val pair = listOf(request("a"), request("b")) // answered by one commit: the next group expects two
            wake()
            pair.forEach { it.await(5, TimeUnit.SECONDS) shouldBe true }
            val started = System.nanoTime()
            val third = request("c")
            wake()
            third.await(5, TimeUnit.SECONDS) shouldBe true
            (System.nanoTime() - started) shouldBeGreaterThan 150_000_000L
            // The commit at the deadline answered one request: the next one is committed at once.
            val alone = System.nanoTime()
            val fourth = request("d")
            wake()
            fourth.await(5, TimeUnit.SECONDS) shouldBe true
            (System.nanoTime() - alone) shouldBeLessThan 150_000_000L
            store.writes.map { it.first } shouldBe listOf(listOf("a", "b"), listOf("c"), listOf("d"))
        }
    }

    test("a group whose commit fails is answered by none until a retry commits all of it") {
        val store = RecordingStore()
        val failures = java.util.concurrent.atomic.AtomicInteger(1)
        store.beforeWrite = { if (failures.getAndDecrement() > 0) throw java.sql.SQLException("disk full") }
        val wakes = java.util.concurrent.LinkedBlockingQueue<() -> Unit>()
        StateJournal(store, waitForCommit = true, later = wakes::add).use { journal ->
            val answered = java.util.concurrent.CountDownLatch(3)
            (1..3).forEach { request ->
                journal.append(put("order-$request"))
                journal.whenCommitted(journal.mark()) { answered.countDown() }
            }
            wakes.poll()()
            answered.await(500, TimeUnit.MILLISECONDS) shouldBe false
            answered.count shouldBe 3
            answered.await(5, TimeUnit.SECONDS) shouldBe true
            store.writes.single() shouldBe ((1..3).map { "order-$it" } to true)
        }
    }

    test("a request is answered only once the commit holding its change returned from the disk") {
        val store = RecordingStore()
        val onDisk = java.util.concurrent.CountDownLatch(1)
        store.beforeWrite = { onDisk.await() }
        StateJournal(store, waitForCommit = true).use { journal ->
            val answered = java.util.concurrent.CountDownLatch(1)
            journal.append(put("order"))
            journal.whenCommitted(journal.mark()) { answered.countDown() }

            answered.await(300, TimeUnit.MILLISECONDS) shouldBe false
            onDisk.countDown()
            answered.await(5, TimeUnit.SECONDS) shouldBe true
            store.writes.single() shouldBe (listOf("order") to true)
        }
    }

    test("a request whose change could not be written before the journal stopped is never answered") {
        val store = RecordingStore()
        store.beforeWrite = { throw java.sql.SQLException("disk full") }
        val answered = java.util.concurrent.CountDownLatch(1)
        StateJournal(store, waitForCommit = true).use { journal ->
            journal.append(put("order"))
            journal.whenCommitted(journal.mark()) { answered.countDown() }
        } // close() gives the failing store a few retries, then stops
        answered.await(200, TimeUnit.MILLISECONDS) shouldBe false
        store.writes shouldBe emptyList()
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
    var beforeWrite: () -> Unit = {}

    override fun write(changes: Collection<StoreChange>, flush: Boolean) {
        beforeWrite()
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
