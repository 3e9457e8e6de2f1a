package org.ktcs.kernel.store

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.longs.shouldBeLessThan
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import java.nio.file.Files
import java.nio.file.Path

/**
 * The journal, not a client's commit, copies SQLite's write-ahead log into the store's file: when it is idle, and
 * under a steady stream once the log has grown, so that the log stays bounded and nothing written is lost.
 */
class StoreCheckpointTest : FunSpec({
    // A row of about 3 KB takes a page of its own, so that the log grows by about a page per row.
    fun row(number: Int) = StoreChange.Put(StoreTable.PLANT_LOCKS, "row-$number", "x".repeat(3_000))

    fun StateJournal.commit(changes: List<StoreChange>) {
        changes.forEach(::append)
        val mark = mark()
        runBlocking { withTimeout(5_000) { awaitCommitted(mark) } }
    }

    fun Path.size(name: String) = resolve(name).let { if (Files.exists(it)) Files.size(it) else 0L }

    test("an idle journal checkpoints its log into the store's file") {
        val directory = Files.createTempDirectory("ktcs-checkpoint-test")
        StateJournal(StateStore.embedded(directory, synchronous = true), waitForCommit = true).use { journal ->
            val before = directory.size(StateStore.FILE_NAME)
            // 50 pages: far below the 1,000 at which SQLite would checkpoint by itself.
            journal.commit((1..50).map(::row))
            val deadline = System.nanoTime() + 5_000_000_000L
            while (directory.size(StateStore.FILE_NAME) - before < 50 * 3_000 && System.nanoTime() < deadline) {
                Thread.sleep(10)
            }
            directory.size(StateStore.FILE_NAME) - before shouldBeGreaterThan 50L * 3_000
        }
    }

    test("under a steady stream the log is checkpointed and stays bounded, and every row is kept") {
        val directory = Files.createTempDirectory("ktcs-checkpoint-test")
        val rows = 3 * StateJournal.CHECKPOINT_CHANGES
        StateJournal(StateStore.embedded(directory, synchronous = true), waitForCommit = true).use { journal ->
            // Commits of 20 rows one after the other: the writer is never idle long enough for an idle checkpoint.
            (0 until rows).chunked(20).forEach { numbers -> journal.commit(numbers.map(::row)) }

            // Without a checkpoint the log would hold all 6,000 rows' pages and their index's (more than 25 MB).
            directory.size("${StateStore.FILE_NAME}-wal") shouldBeLessThan rows / 2 * 4_096L
            directory.size(StateStore.FILE_NAME) shouldBeGreaterThan rows / 2 * 3_000L
        }
        StateStore.embedded(directory, synchronous = true).use { store ->
            var read = 0
            store.rows(StoreTable.PLANT_LOCKS) { read += it.size }
            read shouldBe rows
        }
    }
})
