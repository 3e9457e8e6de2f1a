package org.ktcs.kernel.bench

import org.ktcs.kernel.simulation.LowerBound
import org.ktcs.kernel.simulation.Trip
import java.time.Duration
import java.time.Instant

/**
 * The workload of issue #11 on any plant: [BenchOptions.orders] orders posted at once, run until every one is final
 * or none finished for [BenchOptions.stallSeconds]; the makespan next to its lower bound, what the kernel spent per
 * finished order, how long orders waited for a vehicle, and what the event stream showed of the traffic rules.
 */
class BatchWorkload(private val options: BenchOptions, private val figures: Figures) {
    fun run(ktcs: KtcsUnderTest, orders: BenchOrders, bound: LowerBound, prefix: String) {
        val vehicles = ktcs.client.vehicles().orEmpty().count { it.string("integrationLevel") == "TO_BE_UTILIZED" }
        val batch = orders.next("$prefix-", options.orders)
        EventWatcher(ktcs.client).use { watcher ->
            val stats = ktcs.stats
            val cpuStart = stats?.cpuSeconds()
            val threadStart = stats?.threadCpuSeconds(DemoWorkload.KERNEL_THREAD)
            val threadsStart = stats?.threads()
            val start = System.nanoTime()
            val startInstant = Instant.now()
            OrderPosting.post(ktcs.client, batch, DemoWorkload.CONCURRENT_CLIENTS)
            val end = awaitBatch(watcher, prefix)
            val states = watcher.states(prefix)
            val finished = states.values.count { it == "FINISHED" }
            figures.record("vehicles", vehicles.toDouble())
            figures.record("orders_posted", batch.size.toDouble())
            figures.record("orders_finished", finished.toDouble())
            figures.record("orders_failed", states.values.count { it == "FAILED" || it == "UNROUTABLE" }.toDouble())
            if (stats != null && finished > 0) {
                figures.record("kernel_cpu_per_order_ms", (stats.cpuSeconds() - cpuStart!!) * MILLIS / finished)
                stats.threadCpuSeconds(DemoWorkload.KERNEL_THREAD)?.let { thread ->
                    threadStart?.let {
                        figures.record(
                            "kernel_thread_cpu_per_order_ms",
                            (thread - it) * MILLIS / finished,
                        )
                    }
                }
                threadsStart?.let { recordThreads(ThreadCpu.byKind(it, stats.threads()), finished) }
            }
            val wall = (end - start) / OrderPosting.NANOS_PER_SECOND
            figures.record("makespan_wall_s", wall)
            figures.record("makespan_simulated_s", wall * options.timeFactor)
            recordKernelMakespan(ktcs.client, prefix, startInstant, wall)
            recordFinalShares(watcher.finalTimes(prefix), start, batch.size)
            val trips = batch.map { Trip(it.from, BenchClient.LOAD, it.to, BenchClient.UNLOAD) }
            figures.record("lower_bound_simulated_s", bound.seconds(trips, vehicles))
            val latencies = watcher.assignLatenciesMillis()
            figures.record("assign_latency_p50_ms", quantile(latencies, MEDIAN))
            figures.record("assign_latency_p99_ms", quantile(latencies, P99))
            figures.record("deadlock_notifications", watcher.deadlockNotifications().toDouble())
            figures.record("idle_vehicle_notifications", watcher.idleVehicleNotifications().toDouble())
            figures.record("double_allocations", watcher.doubleAllocations().toDouble())
            figures.record("shared_positions", watcher.sharedPositions().toDouble())
            figures.record("event_stream_missed", watcher.missedEvents().toDouble())
            watcher.eventCounts().toSortedMap().forEach { (topic, count) ->
                figures.record("event_stream_events.$topic", count.toDouble())
            }
            figures.record("event_stream_mib", watcher.eventChars() / BYTES_PER_MIB)
            figures.record("rss_end_mib", stats?.rssMib())
        }
    }

    /**
     * The makespan by the kernel's clock (its orders' finish times) and how much later the bench saw the batch end:
     * the bench's client reads the whole event stream on cores it shares with kTCS and may fall behind it.
     */
    private fun recordKernelMakespan(client: BenchClient, prefix: String, start: Instant, observedWall: Double) {
        val last = try {
            KernelFinishTimes.lastFinished(client, prefix)
        } catch (error: IllegalStateException) {
            return figures.note("makespan_kernel", error.message ?: "no figure")
        } ?: return figures.note("makespan_kernel", "no finished order of the batch in GET /transportOrders")
        val wall = Duration.between(start, last).toNanos() / OrderPosting.NANOS_PER_SECOND
        figures.record("makespan_kernel_wall_s", wall)
        figures.record("makespan_kernel_simulated_s", wall * options.timeFactor)
        figures.record("batch_end_seen_after_kernel_s", observedWall - wall)
    }

    /** The CPU per finished order of the kinds of thread that used most, e.g. `cpu_ms_per_order.kernel: 7.8`. */
    private fun recordThreads(kinds: List<Pair<String, Double>>, finished: Int) {
        val shown = kinds.take(THREAD_KINDS_SHOWN)
        shown.forEach { (kind, seconds) -> figures.record("cpu_ms_per_order.$kind", seconds * MILLIS / finished) }
        val others = kinds.drop(THREAD_KINDS_SHOWN).sumOf { it.second }
        figures.record("cpu_ms_per_order.(other threads)", others * MILLIS / finished)
    }

    /**
     * The wall-clock seconds by which half, nine in ten and 99 in 100 of the posted orders were final
     * (`final_50_percent_wall_s` …): whether the makespan is the whole batch's pace or a few late orders.
     */
    private fun recordFinalShares(finalTimes: List<Long>, start: Long, posted: Int) {
        val sorted = finalTimes.sorted()
        for (percent in FINAL_PERCENTS) {
            val needed = (posted * percent + PERCENT - 1) / PERCENT
            val at = sorted.getOrNull(needed - 1) ?: continue
            figures.record("final_${percent}_percent_wall_s", (at - start) / OrderPosting.NANOS_PER_SECOND)
        }
    }

    /** Waits until every order of the batch is final or none became final for a while; returns when it stopped. */
    private fun awaitBatch(watcher: EventWatcher, prefix: String): Long {
        var finalCount = -1
        var lastProgress = System.nanoTime()
        var lastFinal = lastProgress
        while (true) {
            val states = watcher.states(prefix)
            val final = states.values.count { it in OrderPosting.FINAL_STATES }
            val now = System.nanoTime()
            if (final != finalCount) {
                finalCount = final
                lastProgress = now
                lastFinal = now
            }
            if (final >= options.orders) return lastFinal
            if ((now - lastProgress) / OrderPosting.NANOS_PER_SECOND > options.stallSeconds) {
                figures.note(
                    "stalled",
                    "no order finished for ${options.stallSeconds} s; $final of ${options.orders} final",
                )
                return lastFinal
            }
            Thread.sleep(POLL_MILLIS)
        }
    }

    private companion object {
        const val MILLIS = 1000.0
        const val MEDIAN = 0.5
        const val P99 = 0.99
        const val POLL_MILLIS = 10L
        const val PERCENT = 100
        val FINAL_PERCENTS = listOf(50, 90, 99)
        const val THREAD_KINDS_SHOWN = 8
        const val BYTES_PER_MIB = 1024.0 * 1024.0
    }
}
