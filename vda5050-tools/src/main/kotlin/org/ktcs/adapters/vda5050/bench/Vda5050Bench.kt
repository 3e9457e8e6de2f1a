package org.ktcs.adapters.vda5050.bench

import org.ktcs.adapters.vda5050.broker.BrokerConfig
import org.ktcs.adapters.vda5050.broker.BuiltinBroker
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.mqtt.MqttLink
import org.ktcs.adapters.vda5050.sim.SimulatedVehicle
import org.ktcs.adapters.vda5050.sim.SimulatorOptions
import org.ktcs.adapters.vda5050.sim.simulatedVehicles
import org.ktcs.kernel.bench.BenchOrder
import org.ktcs.kernel.bench.BenchOrders
import org.ktcs.kernel.bench.KtcsUnderTest
import org.ktcs.kernel.bench.ProcStats
import org.ktcs.kernel.bench.quantile
import org.ktcs.kernel.bench.string
import org.ktcs.kernel.persistence.PlantModelFiles
import org.ktcs.kernel.simulation.Fleet
import org.ktcs.kernel.simulation.GridPlant
import java.net.InetAddress
import java.net.ServerSocket
import java.nio.ByteBuffer
import java.nio.file.Files
import java.nio.file.Path
import java.util.Collections
import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit
import kotlin.system.exitProcess

/** The figures of one run. */
data class RunFigures(
    val finished: Int,
    val failed: Int,
    val cpuSeconds: Double,
    val wallSeconds: Double,
    /** kTCS's CPU seconds by thread group ([ThreadCpu]), biggest first. */
    val cpuByGroup: List<Pair<String, Double>> = emptyList(),
    /** kTCS's threads' context switches by thread group ([ThreadSwitches]). */
    val switchesByGroup: Map<String, Long> = emptyMap(),
) {
    val cpuPerOrderMillis: Double get() = perOrder(cpuSeconds)

    /** CPU per finished order without the embedded broker's threads. */
    val cpuPerOrderWithoutBrokerMillis: Double
        get() = perOrder(cpuSeconds - cpuByGroup.filter { it.first == ThreadCpu.BROKER_GROUP }.sumOf { it.second })

    private fun perOrder(seconds: Double) = if (finished == 0) Double.NaN else seconds * MILLIS / finished
}

/**
 * The VDA 5050 benchmark: the same workload on VDA 5050 vehicles (simulated in this process, over kTCS's embedded
 * broker) and on loopback vehicles, each on a kTCS started with the launcher a user runs.
 */
class Vda5050Bench(private val options: Vda5050BenchOptions, private val launcher: Path) {
    private val work = Files.createTempDirectory("ktcs-vda5050-bench")
    private val side = options.grid ?: maxOf(MIN_GRID, Math.ceil(Math.sqrt(options.vehicles / GRID_DENSITY)).toInt())
    private val plant = Fleet.withVehicles(GridPlant(side, side).build(), options.vehicles)
    private val orders = BenchOrders(plant, SEED).next("B", options.orders)

    fun run() {
        if (options.brokerStepRounds > 0) return brokerSteps()
        println(
            "vda5050-bench: ${options.vehicles} vehicles, ${options.orders} orders, ${side}x$side grid, time factor ${options.timeFactor}",
        )
        val (vda, roundTrips) = vdaRun()
        println(line("VDA 5050", vda))
        println(groups(vda))
        val loopback = loopbackRun()
        println(line("loopback", loopback))
        println(groups(loopback))
        val ratio = vda.cpuPerOrderMillis / loopback.cpuPerOrderMillis
        val withoutBroker = vda.cpuPerOrderWithoutBrokerMillis / loopback.cpuPerOrderMillis
        println(
            (
                "kernel CPU per finished order, VDA 5050 / loopback: %.2f, %s " +
                    "(without the embedded broker's threads, which an external broker would run: %.2f, %s)"
                ).format(ratio, againstTarget(ratio), withoutBroker, againstTarget(withoutBroker)),
        )
        println(
            "broker round trip (QoS 0, %d samples): p50 %.2f ms, p99 %.2f ms, max %.2f ms".format(
                roundTrips.size,
                quantile(roundTrips, 0.5) ?: Double.NaN,
                quantile(roundTrips, 0.99) ?: Double.NaN,
                roundTrips.maxOrNull() ?: Double.NaN,
            ),
        )
        printFloor(vda, loopback)
        println("logs: $work")
    }

    private fun brokerSteps() {
        println(
            "vda5050-bench: the embedded broker's steps, ${options.vehicles} vehicles, ${options.brokerStepRounds} rounds",
        )
        BrokerSteps(vdaModel(), SimulatorOptions(timeFactor = options.timeFactor)).run(options.brokerStepRounds)
            .forEach {
                println(
                    "%-24s %6.0f messages/s: %6.1f µs CPU and %.2f context switches per message (broker + extension threads)"
                        .format(it.step, it.messagesPerSecond, it.cpuMicros, it.switches),
                )
            }
    }

    private fun printFloor(vda: RunFigures, loopback: RunFigures) {
        val perSecond = brokerFloor() * MILLIS
        val secondsPerOrder = vda.wallSeconds / vda.finished.coerceAtLeast(1)
        val perOrder = perSecond * secondsPerOrder
        println(
            "floor: the builtin embedded broker alone receiving %d vehicles' messages (no subscriber, %d s): %.1f ms CPU per s"
                .format(options.vehicles, FLOOR_SECONDS, perSecond) +
                ", %.1f ms per finished order at the VDA 5050 run's rate (%.2f s per order), %.2f x loopback's"
                    .format(perOrder, secondsPerOrder, perOrder / loopback.cpuPerOrderMillis),
        )
    }

    private fun againstTarget(ratio: Double) =
        if (ratio <= TARGET_RATIO) "within the target $TARGET_RATIO" else "above the target $TARGET_RATIO"

    private fun line(kind: String, figures: RunFigures) =
        "%-9s finished %d/%d (failed %d) in %.1f s; kTCS CPU %.1f s, %.1f ms per finished order".format(
            kind,
            figures.finished,
            options.orders,
            figures.failed,
            figures.wallSeconds,
            figures.cpuSeconds,
            figures.cpuPerOrderMillis,
        )

    private fun groups(figures: RunFigures) = "          kTCS CPU by thread: " + figures.cpuByGroup
        .filter { it.second >= MIN_GROUP_SECONDS }
        .joinToString { (group, seconds) ->
            "%s %.1f s (%.1f ms/order, %.0f switches/s)".format(
                group,
                seconds,
                seconds * MILLIS / figures.finished.coerceAtLeast(1),
                (figures.switchesByGroup[group] ?: 0L) / figures.wallSeconds,
            )
        }

    private fun vdaRun(): Pair<RunFigures, List<Double>> {
        val model = vdaModel()
        val file = work.resolve("vda5050-plant.xml").also { PlantModelFiles.write(model, it) }
        val broker = freePort()
        val ktcs = KtcsUnderTest.start(
            launcher,
            file,
            freePort(),
            options.timeFactor,
            work.resolve("ktcs-vda5050.log").toFile(),
            listOf("vda5050.embeddedBroker.port=$broker", "kernel.dataDirectory=${work.resolve("data-vda")}"),
        )
        val executor = Executors.newScheduledThreadPool(2) { Thread(it, "vda5050-sim").apply { isDaemon = true } }
        val endpoint = BrokerEndpoint("127.0.0.1", broker, tls = false)
        val simulatorOptions = SimulatorOptions(timeFactor = options.timeFactor)
        ktcs.use {
            waitForBroker(broker)
            val vehicles = simulatedVehicles(model, simulatorOptions).map { SimulatedVehicle(it, endpoint, executor) }
            vehicles.forEach { it.start() }
            val probe = RoundTripProbe(endpoint)
            try {
                ktcs.awaitReady(READY_SECONDS)
                probe.start()
                return measure(ktcs) to probe.samples()
            } finally {
                probe.close()
                vehicles.forEach { runCatching { it.close() } }
                executor.shutdownNow()
            }
        }
    }

    /**
     * The part of the VDA 5050 run's CPU no driver can remove: the embedded broker (kTCS's, with kTCS's configuration,
     * here in the bench's process) receiving the simulated vehicles' state and visualization messages with no
     * subscriber. CPU seconds of its threads per second.
     */
    private fun brokerFloor(): Double {
        val port = freePort()
        val executor = Executors.newScheduledThreadPool(2) { Thread(it, "vda5050-sim").apply { isDaemon = true } }
        BuiltinBroker(BrokerConfig(port = port)).use { broker ->
            broker.start()
            val endpoint = BrokerEndpoint("127.0.0.1", port, tls = false)
            val vehicles = simulatedVehicles(vdaModel(), SimulatorOptions(timeFactor = options.timeFactor))
                .map { SimulatedVehicle(it, endpoint, executor) }
            try {
                vehicles.forEach { it.start() }
                Thread.sleep(TimeUnit.SECONDS.toMillis(FLOOR_WARM_UP_SECONDS))
                val threads = ThreadCpu(ProcStats.self())
                Thread.sleep(TimeUnit.SECONDS.toMillis(FLOOR_SECONDS))
                return threads.byGroup().filter {
                    it.first == ThreadCpu.BROKER_GROUP
                }.sumOf { it.second } / FLOOR_SECONDS
            } finally {
                vehicles.forEach { runCatching { it.close() } }
                executor.shutdownNow()
            }
        }
    }

    private fun vdaModel() = plant.copy(
        vehicles = plant.vehicles.mapIndexed { i, vehicle ->
            vehicle.copy(
                properties = vehicle.properties + mapOf(
                    "tcs:preferredAdapterClass" to "vda5050",
                    "vda5050:version" to "2.0",
                    "vda5050:interfaceName" to "uagv",
                    "vda5050:manufacturer" to "kTCS",
                    "vda5050:serialNumber" to "BENCH-%03d".format(i + 1),
                ),
            )
        },
    )

    private fun loopbackRun(): RunFigures {
        val model = plant.copy(
            vehicles = plant.vehicles.map {
                it.copy(properties = it.properties + ("tcs:preferredAdapterClass" to "loopback"))
            },
        )
        val file = work.resolve("loopback-plant.xml").also { PlantModelFiles.write(model, it) }
        return KtcsUnderTest.start(
            launcher,
            file,
            freePort(),
            options.timeFactor,
            work.resolve("ktcs-loopback.log").toFile(),
            listOf("kernel.dataDirectory=${work.resolve("data-loopback")}"),
        ).use { ktcs ->
            ktcs.awaitReady(READY_SECONDS)
            measure(ktcs)
        }
    }

    /** Posts the orders and waits until every one is final; kTCS's CPU from the first post to the last final order. */
    private fun measure(ktcs: KtcsUnderTest): RunFigures {
        val stats = checkNotNull(ktcs.stats)
        val cpuStart = stats.cpuSeconds()
        val threads = ThreadCpu(stats)
        val switches = ktcs.pid?.let(::ThreadSwitches)
        val start = System.nanoTime()
        orders.forEach { order: BenchOrder -> ktcs.client.postOrder(order.name, order.from, order.to) }
        val deadline = start + TimeUnit.SECONDS.toNanos(options.timeoutSeconds)
        var states = emptyMap<String, Int>()
        while (System.nanoTime() < deadline) {
            states = finalStates(ktcs)
            if (states.values.sum() >= orders.size) break
            Thread.sleep(POLL_MILLIS)
        }
        val cpu = stats.cpuSeconds() - cpuStart
        val wall = (System.nanoTime() - start) / NANOS_PER_SECOND
        val failed = states.filterKeys { it != "FINISHED" }.values.sum()
        val finished = states["FINISHED"] ?: 0
        return RunFigures(finished, failed, cpu, wall, threads.byGroup(), switches?.byGroup().orEmpty())
    }

    private fun finalStates(ktcs: KtcsUnderTest): Map<String, Int> {
        val text = ktcs.client.get("/transportOrders") ?: return emptyMap()
        return kotlinx.serialization.json.Json.parseToJsonElement(text).let {
            it as kotlinx.serialization.json.JsonArray
        }
            .map { it as kotlinx.serialization.json.JsonObject }
            .filter { it.string("name")?.startsWith("B") == true }
            .mapNotNull { it.string("state") }
            .filter { it in FINAL_STATES }
            .groupingBy { it }.eachCount()
    }

    private fun waitForBroker(port: Int) {
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(READY_SECONDS)
        while (System.nanoTime() < deadline) {
            if (runCatching { java.net.Socket("127.0.0.1", port).close() }.isSuccess) return
            Thread.sleep(POLL_MILLIS / 10)
        }
        error("kTCS's embedded broker did not listen on port $port within $READY_SECONDS s")
    }

    private companion object {
        const val SEED = 42L
        const val MIN_GRID = 10
        const val GRID_DENSITY = 100.0 / (40 * 40)
        const val MIN_GROUP_SECONDS = 0.05

        /** Issue #16's target: kTCS's CPU per finished order with VDA 5050 vehicles at most 1.5 times loopback's. */
        const val TARGET_RATIO = 1.5
        const val READY_SECONDS = 120L
        const val POLL_MILLIS = 1000L
        const val NANOS_PER_SECOND = 1e9
        const val FLOOR_SECONDS = 20L
        const val FLOOR_WARM_UP_SECONDS = 10L
        val FINAL_STATES = setOf("FINISHED", "FAILED", "UNROUTABLE", "WITHDRAWN")
    }
}

/** Publishes a timestamp every 100 ms to a topic it subscribes to and keeps the round trips, in milliseconds. */
private class RoundTripProbe(endpoint: BrokerEndpoint) : AutoCloseable {
    private val link = MqttLink("bench-probe-${System.nanoTime()}", endpoint)
    private val samples = Collections.synchronizedList(mutableListOf<Double>())
    private val timer = Executors.newSingleThreadScheduledExecutor { Thread(it, "rtt-probe").apply { isDaemon = true } }

    fun start() {
        link.connect()
        link.subscribe(TOPIC, 0) { payload ->
            samples += (System.nanoTime() - ByteBuffer.wrap(payload).long) / NANOS_PER_MILLI
        }.get()
        timer.scheduleAtFixedRate({
            link.publish(TOPIC, ByteBuffer.allocate(Long.SIZE_BYTES).putLong(System.nanoTime()).array(), 0)
        }, 0, INTERVAL_MILLIS, TimeUnit.MILLISECONDS)
    }

    fun samples(): List<Double> = synchronized(samples) { samples.toList() }

    override fun close() {
        timer.shutdownNow()
        link.close()
    }

    private companion object {
        const val TOPIC = "ktcs/bench/roundTrip"
        const val INTERVAL_MILLIS = 100L
        const val NANOS_PER_MILLI = 1e6
    }
}

private fun freePort(): Int = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }

private const val MILLIS = 1000.0

/** `ktcs vda5050-bench`. */
fun main(args: Array<String>) {
    if ("--help" in args || "-h" in args) {
        println(Vda5050BenchOptions.USAGE)
        return
    }
    val options = try {
        Vda5050BenchOptions.parse(args.toList())
    } catch (error: IllegalArgumentException) {
        System.err.println("ktcs vda5050-bench: ${error.message}\n${Vda5050BenchOptions.USAGE}")
        exitProcess(2)
    }
    val launcher = Path.of(System.getProperty("ktcs.launcher") ?: "ktcs").toAbsolutePath()
    require(Files.isExecutable(launcher)) {
        "the launcher $launcher is missing (run the bench with ./ktcs vda5050-bench)"
    }
    Vda5050Bench(options, launcher).run()
    exitProcess(0)
}
