package org.ktcs.kernel.bench

import java.nio.file.Path

/** The workloads of `ktcs bench`. */
enum class Workload { DEMO, BATCH, RESTART, SOAK }

/**
 * The HTTP client the demo workload creates orders with: the JDK's `HttpClient` ([JDK], what a Java client of kTCS
 * would use) or the bench's lean one ([RAW]: keep-alive sockets, requests encoded beforehand), whose own CPU per
 * request is small enough that the rate it measures is kTCS's.
 */
enum class ClientKind { JDK, RAW }

/**
 * What `ktcs bench` runs.
 *
 * @property url a running kTCS to measure; `null` starts [launcher] for each run.
 * @property pid the process id of the kTCS at [url], for its CPU and memory figures.
 * @property model the plant the orders are drawn from and the started kTCS loads (`null`: the demo plant).
 * @property grid a generated grid plant (as `ktcs simulate --grid` builds it) instead of [model].
 * @property port web port of the started kTCS; 0 takes a free one.
 * @property vehicles the started kTCS's fleet (default: the model's vehicles), each placed on a point of its own.
 * @property cpuBatches sizes of the batches whose kernel CPU per finished order the demo workload measures.
 * @property posts orders each order-creation measurement posts.
 * @property clientKinds the clients order creation is measured with, each in turn.
 * @property poolSize orders in the pool when the demo workload lists them.
 * @property gets `GET /v1/transportOrders` requests timed.
 * @property orders orders the batch workload posts at once.
 * @property stallSeconds how long without a finished order ends a run.
 * @property storedFinal restart: final orders in the state store kTCS starts on.
 * @property storedOpen restart: DISPATCHABLE orders in it.
 * @property soakHours soak: plant hours of operation.
 * @property soakMinutes soak: wall-clock minutes they are compressed into (the loopback time factor follows).
 * @property keepHours soak: plant hours the order-pool sweep keeps a final order.
 */
data class BenchOptions(
    val workload: Workload = Workload.DEMO,
    val url: String? = null,
    val pid: Long? = null,
    val model: Path? = null,
    val grid: Pair<Int, Int>? = null,
    val vehicles: Int? = null,
    val launcher: Path = Path.of("./ktcs"),
    val port: Int = 0,
    val runs: Int = 1,
    val seed: Long = 1,
    val timeFactor: Double = 100.0,
    val cpuBatches: List<Int> = listOf(50, 200),
    val posts: Int = 500,
    val clientKinds: List<ClientKind> = listOf(ClientKind.JDK, ClientKind.RAW),
    val poolSize: Int = 3570,
    val gets: Int = 50,
    val orders: Int = 200,
    val operatingMillis: Long = 5000,
    val stallSeconds: Double = 60.0,
    val settings: List<String> = emptyList(),
    val storedFinal: Int = 100_000,
    val storedOpen: Int = 1_000,
    val soakHours: Double = 24.0,
    val soakMinutes: Double = 40.0,
    val keepHours: Double = 1.0,
)
