package org.ktcs.kernel.bench

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.store.StateStore
import org.ktcs.kernel.store.StoreTable
import java.io.File
import java.io.PrintStream
import java.nio.file.Files
import java.nio.file.Path
import java.sql.DriverManager
import java.util.Locale
import java.util.concurrent.TimeUnit

/**
 * `ktcs bench soak`: [BenchOptions.soakHours] of plant operation compressed into [BenchOptions.soakMinutes] by the
 * loopback time factor, on a kTCS with `persistence.durability=COMMIT` whose order-pool sweep keeps final orders
 * [BenchOptions.keepHours] of plant time. The fleet is kept busy (two open orders per vehicle, a new one posted as
 * one ends), so the orders are as many as the plant's vehicles can carry out in that time. Once per plant hour it
 * prints the store's size, its rows per table, the kernel's memory and the orders so far; the figures at the end say
 * whether the store levelled off once the sweep started.
 */
class SoakWorkload(private val options: BenchOptions, private val figures: Figures, private val out: PrintStream) {
    /** The loopback time factor that fits [BenchOptions.soakHours] into [BenchOptions.soakMinutes]. */
    val timeFactor: Double get() = options.soakHours * MINUTES_PER_HOUR / options.soakMinutes

    private val plantHourMillis: Long get() = (MILLIS_PER_HOUR / timeFactor).toLong()

    /** What the started kTCS needs besides the bench's usual settings: the store and a sweep in plant time. */
    fun settings(data: Path): List<String> = listOf(
        "kernel.dataDirectory=$data",
        "persistence.durability=COMMIT",
        "orderpool.sweepAge=${(options.keepHours * plantHourMillis).toLong()}",
        "orderpool.sweepInterval=$sweepIntervalMillis",
    )

    /** Ten plant minutes between sweeps, as often as the kernel sweeps at most. */
    private val sweepIntervalMillis: Long
        get() = (SWEEP_INTERVAL_PLANT_MILLIS / timeFactor).toLong().coerceAtLeast(MIN_SWEEP_MILLIS)

    fun run(model: PlantModel, data: Path, start: () -> KtcsUnderTest) {
        figures.note(
            "soak",
            "${options.soakHours} plant hours in ${options.soakMinutes} min (loopback.timeFactor=${"%.1f".format(
                Locale.ROOT,
                timeFactor,
            )}), final orders kept ${options.keepHours} plant h, durability COMMIT",
        )
        figures.note("kernel", "started by the bench: ${options.launcher} --no-build, loopback.timeFactor=$timeFactor")
        start().use { ktcs ->
            ktcs.awaitReady(READY_SECONDS)
            EventWatcher(ktcs.client).use { watcher -> drive(ktcs, watcher, model, data) }
        }
    }

    private fun drive(ktcs: KtcsUnderTest, watcher: EventWatcher, model: PlantModel, data: Path) {
        val orders = BenchOrders(model, options.seed)
        val prefix = "Soak-${System.currentTimeMillis().toString(RADIX)}-"
        val open = OPEN_PER_VEHICLE * model.vehicles.size.coerceAtLeast(1)
        val started = System.nanoTime()
        val end = started + (options.soakMinutes * NANOS_PER_MINUTE).toLong()
        var posted = 0
        var nextSample = started
        var hour = 0
        val samples = ArrayList<Sample>()
        out.println(Sample.HEADER)
        while (true) {
            val now = System.nanoTime()
            if (now >= nextSample) {
                val sample = sample(hour, (now - started) / NANOS_PER_SECOND, ktcs, watcher, prefix, posted, data)
                samples += sample
                out.println(sample.line())
                out.flush()
                hour++
                nextSample = started + hour * plantHourMillis * NANOS_PER_MILLI
            }
            if (now >= end) break
            val ended = watcher.states(prefix).values.count { it in FINAL_STATES }
            orders.next("$prefix$posted-", (open - (posted - ended)).coerceAtLeast(0)).forEach {
                ktcs.client.postOrder(it.name, it.from, it.to)
                posted++
            }
            Thread.sleep(POLL_MILLIS)
        }
        record(samples)
    }

    private fun sample(
        hour: Int,
        wallSeconds: Double,
        ktcs: KtcsUnderTest,
        watcher: EventWatcher,
        prefix: String,
        posted: Int,
        data: Path,
    ): Sample {
        val states = watcher.states(prefix).values
        return Sample(
            hour = hour,
            wallSeconds = wallSeconds,
            dbMib = mib(data.resolve(StateStore.FILE_NAME)),
            walMib = mib(data.resolve("${StateStore.FILE_NAME}-wal")),
            rows = rowsPerTable(data),
            rssMib = ktcs.stats?.rssMib(),
            heapMib = ktcs.pid?.let(::heapAfterGcMib),
            posted = posted,
            finished = states.count { it == "FINISHED" },
            failed = states.count { it == "FAILED" || it == "UNROUTABLE" },
        )
    }

    private fun record(samples: List<Sample>) {
        val last = samples.lastOrNull() ?: return
        val settled = samples.filter { it.hour >= options.keepHours + 1 }
        figures.record("plant hours run", last.hour.toDouble())
        figures.record("orders posted", last.posted.toDouble())
        figures.record("orders finished", last.finished.toDouble())
        figures.record("orders failed", last.failed.toDouble())
        figures.record("orders finished per plant hour", last.finished / last.hour.coerceAtLeast(1).toDouble())
        figures.record("store at the end (MiB, db + wal)", last.storeMib)
        figures.record("store, largest (MiB, db + wal)", samples.maxOf { it.storeMib })
        settled.firstOrNull()?.let { first ->
            figures.record("store once the sweep runs (MiB, plant hour ${first.hour})", first.storeMib)
            val mostRows = settled.maxOfOrNull { it.orderRows()?.toDouble() ?: 0.0 }
            figures.record("order rows, most once the sweep runs", mostRows)
            figures.record("RSS once the sweep runs (MiB)", first.rssMib)
            figures.record("heap after GC once the sweep runs (MiB)", first.heapMib)
        }
        figures.record("RSS at the end (MiB)", last.rssMib)
        figures.record("heap after GC at the end (MiB)", last.heapMib)
    }

    /** Rows per table, counted in a copy of the store (kTCS holds the file itself exclusively); `null` if unreadable. */
    private fun rowsPerTable(data: Path): Map<StoreTable, Long>? {
        val copy = Files.createTempDirectory("ktcs-soak-copy")
        return try {
            listOf(StateStore.FILE_NAME, "${StateStore.FILE_NAME}-wal").forEach { name ->
                val file = data.resolve(name)
                if (Files.exists(file)) Files.copy(file, copy.resolve(name))
            }
            DriverManager.getConnection("jdbc:sqlite:${copy.resolve(StateStore.FILE_NAME)}").use { connection ->
                connection.createStatement().use { statement ->
                    StoreTable.entries.associateWith { table ->
                        statement.executeQuery("SELECT count(*) FROM ${table.sqlName}").use {
                            it.next()
                            it.getLong(1)
                        }
                    }
                }
            }
        } catch (error: Exception) {
            null
        } finally {
            copy.toFile().deleteRecursively()
        }
    }

    /**
     * The kernel's heap in use right after a full collection, by `jcmd` (`null` where it cannot attach): the sum of
     * the generations' (or G1's heap's) "used", without metaspace.
     */
    private fun heapAfterGcMib(pid: Long): Double? = runCatching {
        jcmd(pid, "GC.run")
        jcmd(pid, "GC.heap_info").lines()
            .filter { "Metaspace" !in it && "class space" !in it }
            .mapNotNull { USED.find(it)?.groupValues?.get(1)?.toDouble() }
            .takeIf { it.isNotEmpty() }
            ?.sum()?.div(KIB_PER_MIB)
    }.getOrNull()

    private fun jcmd(pid: Long, command: String): String {
        val process = ProcessBuilder("jcmd", "$pid", command).redirectErrorStream(true).start()
        val text = process.inputStream.bufferedReader().readText()
        process.waitFor(JCMD_SECONDS, TimeUnit.SECONDS)
        return text
    }

    private fun mib(file: Path): Double = if (Files.exists(file)) Files.size(file) / BYTES_PER_MIB else 0.0

    /** One line of the soak's progress: what it had done and what the store and the kernel held after [hour]. */
    private data class Sample(
        val hour: Int,
        val wallSeconds: Double,
        val dbMib: Double,
        val walMib: Double,
        val rows: Map<StoreTable, Long>?,
        val rssMib: Double?,
        val heapMib: Double?,
        val posted: Int,
        val finished: Int,
        val failed: Int,
    ) {
        val storeMib: Double get() = dbMib + walMib

        fun orderRows(): Long? = rows?.get(StoreTable.TRANSPORT_ORDERS)

        fun line(): String {
            val counts = StoreTable.entries.joinToString(" ") { "%7s".format(rows?.get(it)?.toString() ?: "?") }
            return String.format(
                Locale.ROOT,
                "%4d %7.0f %8.2f %7.2f %s %7s %7s %7d %8d %6d %7d",
                hour,
                wallSeconds,
                dbMib,
                walMib,
                counts,
                rssMib?.let { "%.0f".format(Locale.ROOT, it) } ?: "?",
                heapMib?.let { "%.1f".format(Locale.ROOT, it) } ?: "?",
                posted,
                finished,
                failed,
                rows?.get(StoreTable.TRANSPORT_ORDERS)?.let { (posted - it).coerceAtLeast(0) } ?: -1,
            )
        }

        companion object {
            val HEADER = "hour  wall s    db MiB wal MiB  orders    seqs vehicle   locks  notifs  values" +
                "  RSS MiB heapMiB  posted finished failed   swept"
        }
    }

    private companion object {
        const val MINUTES_PER_HOUR = 60.0
        const val MILLIS_PER_HOUR = 3_600_000.0
        const val SWEEP_INTERVAL_PLANT_MILLIS = 600_000.0
        const val MIN_SWEEP_MILLIS = 1_000L
        const val OPEN_PER_VEHICLE = 2
        const val POLL_MILLIS = 50L
        const val READY_SECONDS = 120L
        const val RADIX = 36
        const val NANOS_PER_SECOND = 1e9
        const val NANOS_PER_MINUTE = 6e10
        const val NANOS_PER_MILLI = 1_000_000L
        const val BYTES_PER_MIB = 1_048_576.0
        const val KIB_PER_MIB = 1024.0
        const val JCMD_SECONDS = 30L
        val USED = Regex("used (\\d+)K")
        val FINAL_STATES = setOf("FINISHED", "FAILED", "UNROUTABLE")
    }
}
