package org.ktcs.kernel.bench

/**
 * The workload of issue #12, as openTCS was measured with it: start-up, memory, kernel CPU per finished order for a
 * small and a larger batch, order creation with one and with eight clients, and listing a full order pool.
 */
class DemoWorkload(private val options: BenchOptions, private val figures: Figures) {
    fun run(ktcs: KtcsUnderTest, orders: BenchOrders, prefix: String) {
        figures.note("clients", CLIENTS_NOTE)
        if (options.url == null) figures.record("launch_ready_s", ktcs.readySeconds)
        figures.record("rss_ready_mib", ktcs.stats?.rssMib())
        unknownOrder(ktcs)
        options.cpuBatches.forEach { size -> cpuPerOrder(ktcs, orders.next("$prefix-cpu$size-", size), size) }
        options.clientKinds.forEach { kind -> creation(ktcs, orders, prefix, kind) }
        val pool = countOrders(ktcs)
        if (pool < options.poolSize) {
            OrderPosting.post(ktcs.client, orders.next("$prefix-fill-", options.poolSize - pool), CONCURRENT_CLIENTS)
        }
        listOrders(ktcs)
        figures.record("rss_end_mib", ktcs.stats?.rssMib())
    }

    /** Order creation with 1 and with 8 clients of [kind]; the JDK client's figures carry no suffix. */
    private fun creation(ktcs: KtcsUnderTest, orders: BenchOrders, prefix: String, kind: ClientKind) {
        val suffix = if (kind == ClientKind.JDK) "" else "_${kind.name.lowercase()}"
        val tag = kind.name.lowercase()
        val single = posted(ktcs, "create_1_client$suffix", orders.next("$prefix-c1$tag-", options.posts), 1, kind)
        figures.record("post_p50${suffix}_ms", quantile(single.latenciesMillis, MEDIAN))
        val eight = orders.next("$prefix-c8$tag-", options.posts)
        posted(ktcs, "create_8_clients$suffix", eight, CONCURRENT_CLIENTS, kind)
    }

    /**
     * Posts [batch] and records the rate, the client's CPU, and kTCS's CPU per POST (the process, the kernel thread,
     * the kinds of thread that used most), all over the same window: the POSTs alone, without the clients' set-up.
     */
    private fun posted(
        ktcs: KtcsUnderTest,
        name: String,
        batch: List<BenchOrder>,
        clients: Int,
        kind: ClientKind,
    ): PostingResult {
        val cpu = ktcs.stats?.let { CpuWindow(it) }
        val result = OrderPosting.post(ktcs.client, batch, clients, kind, { cpu?.start() }, { cpu?.stop() })
        record(name, result)
        if (cpu == null) return result
        figures.record("${name}_cpu_per_post_ms", cpu.processSeconds * MILLIS / result.count)
        recordThreads(name, cpu.byKind, result.count)
        cpu.kernelThreadSeconds?.let {
            figures.record("${name}_kernel_thread_cpu_per_post_ms", it * MILLIS / result.count)
        }
        return result
    }

    /** kTCS's CPU between [start] and [stop]: the process's, the `kernel` thread's and by kind of thread. */
    private class CpuWindow(private val stats: ProcStats) {
        private var process = 0.0
        private var kernelThread: Double? = null
        private var threads: Map<Long, Pair<String, Double>> = emptyMap()
        var processSeconds = 0.0
            private set
        var kernelThreadSeconds: Double? = null
            private set
        var byKind: List<Pair<String, Double>> = emptyList()
            private set

        fun start() {
            process = stats.cpuSeconds()
            kernelThread = stats.threadCpuSeconds(KERNEL_THREAD)
            threads = stats.threads()
        }

        fun stop() {
            processSeconds = stats.cpuSeconds() - process
            val end = stats.threadCpuSeconds(KERNEL_THREAD)
            kernelThreadSeconds = kernelThread?.let { start -> end?.let { it - start } }
            byKind = ThreadCpu.byKind(threads, stats.threads())
        }
    }

    /** The CPU per POST of the kinds of thread that used most, e.g. `create_8_clients_cpu_ms_per_post.kernel: 0.03`. */
    private fun recordThreads(name: String, kinds: List<Pair<String, Double>>, posts: Int) {
        kinds.take(THREAD_KINDS_SHOWN).forEach { (kind, seconds) ->
            figures.record("${name}_cpu_ms_per_post.$kind", seconds * MILLIS / posts)
        }
    }

    private fun cpuPerOrder(ktcs: KtcsUnderTest, batch: List<BenchOrder>, size: Int) {
        val stats = ktcs.stats
        val cpuStart = stats?.cpuSeconds()
        val threadStart = stats?.threadCpuSeconds(KERNEL_THREAD)
        val threadsStart = stats?.threads()
        val wallStart = System.nanoTime()
        OrderPosting.post(ktcs.client, batch, 1)
        val states = OrderPosting.awaitFinal(ktcs.client, batch.map { it.name }, options.stallSeconds)
        val finished = states.values.count { it == "FINISHED" }
        figures.record("orders_${size}_finished", finished.toDouble())
        figures.record("orders_${size}_wall_s", (System.nanoTime() - wallStart) / OrderPosting.NANOS_PER_SECOND)
        if (stats == null || finished == 0) return
        figures.record("kernel_cpu_per_order_${size}_ms", (stats.cpuSeconds() - cpuStart!!) * MILLIS / finished)
        val thread = stats.threadCpuSeconds(KERNEL_THREAD)
        if (thread != null && threadStart != null) {
            figures.record("kernel_thread_cpu_per_order_${size}_ms", (thread - threadStart) * MILLIS / finished)
        }
        threadsStart?.let { start ->
            ThreadCpu.byKind(start, stats.threads()).take(THREAD_KINDS_SHOWN).forEach { (kind, seconds) ->
                figures.record("kernel_cpu_per_order_${size}_ms.$kind", seconds * MILLIS / finished)
            }
        }
    }

    private fun record(name: String, result: PostingResult) {
        figures.record("${name}_per_s", result.perSecond)
        figures.record("${name}_client_cpu_s", result.clientCpuSeconds)
        // 1.0 means the client kept one of the machine's cores busy: a rate it may have limited itself.
        figures.record("${name}_client_cpu_share", result.clientCpuSeconds / result.wallSeconds)
        recordWindow(name, result)
    }

    /**
     * Where the timed window went: the latencies' mean and tail (the rate follows the mean, not the p50), the first
     * answer's time after the clock started, and the share of the summed latency spent in POSTs slower than 1 ms.
     */
    private fun recordWindow(name: String, result: PostingResult) {
        val latencies = result.latenciesMillis
        if (latencies.isEmpty()) return
        figures.record("${name}_latency_mean_ms", latencies.average())
        figures.record("${name}_latency_p99_ms", quantile(latencies, P99))
        figures.record("${name}_latency_max_ms", latencies.max())
        figures.record("${name}_first_answer_ms", result.answeredAtMillis.minOrNull())
        figures.record("${name}_slow_share", latencies.filter { it > SLOW_MILLIS }.sum() / latencies.sum())
    }

    /**
     * `GET /v1/transportOrders` timed with the JDK's client (figures without a suffix) and, if the lean client is
     * measured, with it too (`_raw`): reading megabytes through the JDK's client takes it longer than kTCS takes to
     * answer, and the lean client's figure is kTCS's.
     */
    private fun listOrders(ktcs: KtcsUnderTest) {
        timedList(ktcs, "") { ktcs.client.getDiscarding("/transportOrders") }
        if (ClientKind.RAW in options.clientKinds && ktcs.client.baseUrl.startsWith("http:")) {
            val request = RawHttpConnection.getRequest(ktcs.client.baseUrl, "/transportOrders")
            RawHttpConnection(ktcs.client.baseUrl).use { connection ->
                timedList(ktcs, "_raw") { connection.exchangeDiscarding(request) }
            }
        }
        figures.record("get_orders_pool", countOrders(ktcs).toDouble())
    }

    private fun timedList(ktcs: KtcsUnderTest, suffix: String, get: () -> Long) {
        val latencies = ArrayList<Double>()
        var bytes = 0L
        val cpuStart = ktcs.stats?.cpuSeconds()
        repeat(options.gets) {
            val start = System.nanoTime()
            bytes = get()
            latencies += (System.nanoTime() - start) / OrderPosting.NANOS_PER_MILLI
        }
        val cpuEnd = ktcs.stats?.cpuSeconds()
        if (cpuStart != null && cpuEnd != null && options.gets > 0) {
            // kTCS's share of a GET's latency: the rest is the client reading megabytes, and the machine.
            figures.record("get_orders_cpu${suffix}_ms", (cpuEnd - cpuStart) * MILLIS / options.gets)
        }
        figures.record("get_orders_bytes$suffix", bytes.toDouble())
        figures.record("get_orders_p50${suffix}_ms", quantile(latencies, MEDIAN))
        figures.record("get_orders_p95${suffix}_ms", quantile(latencies, P95))
    }

    /** `GET` of an order that does not exist, on one keep-alive connection of an idle kTCS: latency and CPU. */
    private fun unknownOrder(ktcs: KtcsUnderTest) {
        if (!ktcs.client.baseUrl.startsWith("http:")) return
        val request = RawHttpConnection.getRequest(ktcs.client.baseUrl, BenchClient.orderPath("no-such-order"))
        RawHttpConnection(ktcs.client.baseUrl).use { connection ->
            repeat(UNKNOWN_ORDER_WARM_UP) { connection.exchange(request) }
            val cpuStart = ktcs.stats?.cpuSeconds()
            val latencies = ArrayList<Double>()
            repeat(UNKNOWN_ORDER_GETS) {
                val start = System.nanoTime()
                val status = connection.exchange(request).status
                check(status == NOT_FOUND) { "GET of an unknown order answered $status, not $NOT_FOUND" }
                latencies += (System.nanoTime() - start) / OrderPosting.NANOS_PER_MILLI
            }
            figures.record("get_unknown_order_p50_ms", quantile(latencies, MEDIAN))
            val cpuEnd = ktcs.stats?.cpuSeconds()
            if (cpuStart != null && cpuEnd != null) {
                figures.record("get_unknown_order_cpu_ms", (cpuEnd - cpuStart) * MILLIS / UNKNOWN_ORDER_GETS)
            }
        }
    }

    private fun countOrders(ktcs: KtcsUnderTest): Int =
        ktcs.client.get("/transportOrders")?.let { kotlinx.serialization.json.Json.parseToJsonElement(it) }
            ?.let { (it as kotlinx.serialization.json.JsonArray).size } ?: 0

    companion object {
        const val KERNEL_THREAD = "kernel"
        private const val CLIENTS_NOTE = "create_*/post_p50 without a suffix: the JDK's HttpClient; " +
            "*_raw: the bench's lean client (keep-alive sockets, requests encoded beforehand)"
        const val CONCURRENT_CLIENTS = 8
        private const val THREAD_KINDS_SHOWN = 6
        private const val MILLIS = 1000.0
        private const val MEDIAN = 0.5
        private const val P95 = 0.95
        private const val P99 = 0.99
        private const val SLOW_MILLIS = 1.0
        private const val UNKNOWN_ORDER_WARM_UP = 300
        private const val UNKNOWN_ORDER_GETS = 2000
        private const val NOT_FOUND = 404
    }
}
