package org.ktcs.kernel.bench

import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger

/** What posting a set of orders took: wall time, each request's latency and the bench's own CPU time. */
data class PostingResult(
    val count: Int,
    val wallSeconds: Double,
    val latenciesMillis: List<Double>,
    val clientCpuSeconds: Double,
) {
    val perSecond: Double get() = count / wallSeconds
}

/** Posts orders through the web API with a number of concurrent clients, as fast as kTCS answers. */
object OrderPosting {
    /**
     * Posts [orders] with [clients] concurrent clients of [kind], each order once; every POST must be answered 200.
     * The raw client's requests are encoded and its connections opened before the clock starts.
     */
    fun post(
        client: BenchClient,
        orders: List<BenchOrder>,
        clients: Int,
        kind: ClientKind = ClientKind.JDK,
    ): PostingResult {
        val requests = if (kind == ClientKind.RAW) rawRequests(client.baseUrl, orders) else null
        val connections = requests?.let { List(clients) { RawHttpConnection(client.baseUrl) } }
        try {
            return timed(orders.size, clients) { worker, index ->
                val order = orders[index]
                if (connections == null) {
                    client.postOrder(order.name, order.from, order.to)
                } else {
                    val answer = connections[worker].exchange(requests[index])
                    check(answer.status == HTTP_OK) { "POST order ${order.name} answered ${answer.status}" }
                }
            }
        } finally {
            connections?.forEach { it.close() }
        }
    }

    private fun rawRequests(baseUrl: String, orders: List<BenchOrder>): List<ByteArray> = orders.map {
        RawHttpConnection.postRequest(baseUrl, BenchClient.orderPath(it.name), BenchClient.orderBody(it.from, it.to))
    }

    /** Runs [send] for every index below [count] on [clients] threads (each its worker number), timing each call. */
    private fun timed(count: Int, clients: Int, send: (worker: Int, index: Int) -> Unit): PostingResult {
        val self = ProcStats.self()
        val latencies = DoubleArray(count)
        val next = AtomicInteger()
        val cpuStart = self.cpuSeconds()
        val start = System.nanoTime()
        val pool = Executors.newFixedThreadPool(clients)
        val failures = List(clients) { worker ->
            pool.submit<Throwable?> {
                runCatching {
                    while (true) {
                        val index = next.getAndIncrement()
                        if (index >= count) break
                        val sent = System.nanoTime()
                        send(worker, index)
                        latencies[index] = (System.nanoTime() - sent) / NANOS_PER_MILLI
                    }
                }.exceptionOrNull()
            }
        }.mapNotNull { it.get() }
        pool.shutdown()
        pool.awaitTermination(1, TimeUnit.MINUTES)
        val wall = (System.nanoTime() - start) / NANOS_PER_SECOND
        failures.firstOrNull()?.let { throw IllegalStateException("posting orders failed: ${it.message}", it) }
        return PostingResult(count, wall, latencies.toList(), self.cpuSeconds() - cpuStart)
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
}
