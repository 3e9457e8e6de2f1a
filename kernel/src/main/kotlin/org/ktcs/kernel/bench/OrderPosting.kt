package org.ktcs.kernel.bench

import java.util.concurrent.CyclicBarrier
import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger

/**
 * What posting a set of orders took: wall time, each request's latency, when each was answered (milliseconds after
 * the clock started) and the bench's own CPU time.
 */
data class PostingResult(
    val count: Int,
    val wallSeconds: Double,
    val latenciesMillis: List<Double>,
    val clientCpuSeconds: Double,
    val answeredAtMillis: List<Double> = emptyList(),
) {
    val perSecond: Double get() = count / wallSeconds
}

/** Posts orders through the web API with a number of concurrent clients, as fast as kTCS answers. */
object OrderPosting {
    /**
     * Posts [orders] with [clients] concurrent clients of [kind], each order once; every POST must be answered 200.
     * Only the POSTs are timed, as a client that measures kTCS times them: the raw client's requests are encoded, the
     * client threads started and each one's connection opened (the JDK client's by a `GET` of an unknown order)
     * before the clock starts. [atClockStart] and [atClockStop] run right at the clock's start and stop (to read
     * kTCS's CPU over the same window).
     */
    fun post(
        client: BenchClient,
        orders: List<BenchOrder>,
        clients: Int,
        kind: ClientKind = ClientKind.JDK,
        atClockStart: () -> Unit = {},
        atClockStop: () -> Unit = {},
    ): PostingResult {
        val requests = if (kind == ClientKind.RAW) rawRequests(client.baseUrl, orders) else null
        val connections = requests?.let { List(clients) { RawHttpConnection(client.baseUrl) } }
        val window = Window(orders.size, clients, atClockStart, atClockStop)
        try {
            return window.run(
                prepare = { if (connections == null) client.orderState(WARM_UP_ORDER) },
                send = { worker, index ->
                    val order = orders[index]
                    if (connections == null) {
                        client.postOrder(order.name, order.from, order.to)
                    } else {
                        val answer = connections[worker].exchange(requests[index])
                        check(answer.status == HTTP_OK) { "POST order ${order.name} answered ${answer.status}" }
                    }
                },
            )
        } finally {
            connections?.forEach { it.close() }
        }
    }

    private fun rawRequests(baseUrl: String, orders: List<BenchOrder>): List<ByteArray> = orders.map {
        RawHttpConnection.postRequest(baseUrl, BenchClient.orderPath(it.name), BenchClient.orderBody(it.from, it.to))
    }

    /**
     * Runs `send` for every index below [count] on [clients] threads (each its worker number), timing each call. The
     * clock starts once every thread has run `prepare` and waits at the start line, and stops when the last call
     * returns.
     */
    private class Window(
        private val count: Int,
        private val clients: Int,
        private val atClockStart: () -> Unit,
        private val atClockStop: () -> Unit,
    ) {
        private val self = ProcStats.self()
        private val latencies = DoubleArray(count)
        private val answeredAt = DoubleArray(count)
        private val next = AtomicInteger()
        private var cpuStart = 0.0
        private var start = 0L

        // The barrier's action runs in the last thread to arrive, before any is released: the clock's start.
        private val startLine = CyclicBarrier(clients) {
            atClockStart()
            cpuStart = self.cpuSeconds()
            start = System.nanoTime()
        }

        fun run(prepare: () -> Unit, send: (worker: Int, index: Int) -> Unit): PostingResult {
            val pool = Executors.newFixedThreadPool(clients)
            val failures = try {
                val workers = List(clients) { worker ->
                    pool.submit<Throwable?> { runCatching { work(worker, prepare, send) }.exceptionOrNull() }
                }
                workers.mapNotNull { it.get() }
            } finally {
                pool.shutdown()
            }
            val wall = (System.nanoTime() - start) / NANOS_PER_SECOND
            val clientCpu = self.cpuSeconds() - cpuStart
            atClockStop()
            pool.awaitTermination(1, TimeUnit.MINUTES)
            failures.firstOrNull()?.let { throw IllegalStateException("posting orders failed: ${it.message}", it) }
            return PostingResult(count, wall, latencies.toList(), clientCpu, answeredAt.toList())
        }

        private fun work(worker: Int, prepare: () -> Unit, send: (worker: Int, index: Int) -> Unit) {
            try {
                prepare()
            } finally {
                startLine.await()
            }
            while (true) {
                val index = next.getAndIncrement()
                if (index >= count) break
                val sent = System.nanoTime()
                send(worker, index)
                val answered = System.nanoTime()
                latencies[index] = (answered - sent) / NANOS_PER_MILLI
                answeredAt[index] = (answered - start) / NANOS_PER_MILLI
            }
        }
    }

    /**
     * Waits until every order in [names] is in a final state, asking for the oldest unfinished one at a time (so
     * waiting costs kTCS a few requests per second, not a list per poll), or until none finished for
     * [stallSeconds]. Returns the final states by name.
     */
    fun awaitFinal(client: BenchClient, names: List<String>, stallSeconds: Double): Map<String, String> {
        val done = LinkedHashMap<String, String>()
        var lastProgress = System.nanoTime()
        var index = 0
        while (index < names.size) {
            val state = client.orderState(names[index])
            if (state in FINAL_STATES) {
                done[names[index]] = state!!
                index++
                lastProgress = System.nanoTime()
                continue
            }
            if ((System.nanoTime() - lastProgress) / NANOS_PER_SECOND > stallSeconds) break
            Thread.sleep(POLL_MILLIS)
        }
        return done
    }

    val FINAL_STATES = setOf("FINISHED", "FAILED", "UNROUTABLE")
    const val NANOS_PER_MILLI = 1e6
    const val NANOS_PER_SECOND = 1e9
    private const val HTTP_OK = 200
    private const val POLL_MILLIS = 100L
    private const val WARM_UP_ORDER = "bench-warm-up-no-such-order"
}
