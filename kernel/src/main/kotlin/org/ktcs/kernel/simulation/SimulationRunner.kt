package org.ktcs.kernel.simulation

import org.koin.dsl.module
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.routing.Router
import org.ktcs.extension.KernelDefaults
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.context.RealTimeKernelContext
import org.ktcs.kernel.context.VirtualTimeKernelContext
import org.ktcs.kernel.dispatching.DefaultDispatcher
import org.ktcs.kernel.dispatching.VehicleAvailability
import org.ktcs.kernel.routerConfiguration
import org.ktcs.kernel.routing.DefaultRouter
import org.ktcs.kernel.scheduling.DefaultScheduler
import java.lang.management.ManagementFactory
import kotlin.random.Random

/**
 * Runs the kernel with loopback vehicles on random transport orders (load at one station, unload at another) and
 * measures it. Posts all [orders] at once, as the benchmark client does, and waits until all are final (or
 * [limitSimulatedMillis] of kernel time passed, or an hour of vehicle time without any order ending).
 *
 * Time: the kernel runs exactly as `ktcs` runs it (same watchdog period, dispatcher runs and driver reports, with
 * loopback vehicles [timeFactor] times faster than the kernel clock), on virtual time (as fast as the machine can) or,
 * with [realTime], on the wall clock.
 */
class SimulationRunner(
    private val model: PlantModel,
    private val config: KtcsConfig,
    private val extensions: List<KtcsExtension>,
    private val orders: Int,
    seed: Long,
    private val loadOperation: String = "Load cargo",
    private val unloadOperation: String = "Unload cargo",
    private val limitSimulatedMillis: Long = 30L * 86_400_000,
    private val realTime: Boolean = false,
) {
    private val random = Random(seed)

    // Vehicles of another driver than the loopback one are taken to run on the kernel clock.
    private val timeFactor = loopbackSetting("loopback.timeFactor") as Double? ?: 1.0
    private val sources = model.locations.filter {
        model.locationType(it.type)?.allowedOperations?.contains(loadOperation) ==
            true
    }.map { it.name }
    private val targets = model.locations.filter {
        model.locationType(it.type)?.allowedOperations?.contains(unloadOperation) ==
            true
    }.map { it.name }

    init {
        require(orders >= 1) { "--orders must be at least 1, was $orders" }
        require(sources.isNotEmpty() && targets.size >= 2) {
            "plant '${model.name}' needs locations that allow '$loadOperation' and at least two that allow '$unloadOperation'"
        }
    }

    fun run(): SimulationReport {
        val router = TimedRouter(DefaultRouter(routerConfiguration(config)))
        val clock = if (realTime) RealTimeKernelContext() else VirtualTimeKernelContext()
        var dispatcher: TimedDispatcher? = null
        val overrides = module {
            single<Router> { router }
            // The default dispatcher timed, also inside an extension's dispatcher that wraps it.
            single<KernelDefaults> {
                val scope = this
                object : KernelDefaults {
                    override fun dispatcher(): Dispatcher =
                        TimedDispatcher(DefaultDispatcher(scope.get(), scope.get(), scope.get()), clock::elapsedMillis)
                            .also { dispatcher = it }
                }
            }
        }
        SimulationKernel(model, config, extensions.map { it.module() } + overrides, clock).use { kernel ->
            val audit = AllocationAudit()
            val latencies = AssignLatencies(kernel) { dispatcher?.runStartedAt }
            val ledger = VehicleTimeLedger(
                kernel.clock::elapsedMillis,
                timeFactor,
                kernel.core.orders::get,
            ) { it.startsWith(ORDER_PREFIX) }
            // The breakdown reads the kernel's own scheduler; a replaced one is not broken down.
            val scheduler = kernel.core.scheduler as? DefaultScheduler
            val breakdown = scheduler?.let { HeldBackBreakdown(model, it) }
            var final = 0
            var lastProgress = 0L
            val creations = (0 until orders).map(::randomOrder)
            val threads = ManagementFactory.getThreadMXBean()
            val kernelThread = kernel.onKernel {
                kernel.core.events.listen(audit::onEvent)
                kernel.core.events.listen(latencies::onEvent)
                kernel.core.events.listen(ledger::onEvent)
                kernel.core.events.listen { event ->
                    if (event is TransportOrderEvent && event.isSimulationOrderEnding()) {
                        final++
                        lastProgress = kernel.clock.elapsedMillis()
                    }
                }
                Thread.currentThread().id
            }
            val cpuStart = threads.getThreadCpuTime(kernelThread)
            val wallStart = System.nanoTime()
            val startMillis = kernel.onKernel { kernel.clock.elapsedMillis() }
            kernel.onKernel {
                lastProgress = kernel.clock.elapsedMillis()
                ledger.start(kernel.core.plant.vehicles())
                breakdown?.let { sampleEvery(kernel, it) }
                creations.forEach { kernel.core.createTransportOrder(it) }
                // On the wall clock, creating thousands of orders takes a while: the wave starts with the last.
                latencies.postedAt = kernel.clock.elapsedMillis()
            }
            val stallLimit = (STALL_LIMIT_MILLIS / timeFactor).toLong()
            kernel.runUntil {
                val elapsed = kernel.clock.elapsedMillis()
                final >= orders || elapsed - lastProgress > stallLimit || elapsed - startMillis > limitSimulatedMillis
            }
            return kernel.onKernel {
                val cpu = threads.getThreadCpuTime(kernelThread) - cpuStart
                report(kernel, (kernel.clock.elapsedMillis() - startMillis) * timeFactor / 1000.0, cpu / 1e9).copy(
                    wallSeconds = (System.nanoTime() - wallStart) / 1e9,
                    assignLatencyMillis = Percentiles.of(latencies.millis),
                    assignWaitMillis = Percentiles.of(latencies.waitMillis),
                    dispatchRunMillis = Percentiles.of(dispatcher?.durationsNanos.orEmpty().map { it / 1e6 }),
                    dispatchRuns = dispatcher?.durationsNanos?.size ?: 0,
                    firstWaveAssignments = latencies.firstWave,
                    firstWaveMillis = latencies.firstWaveMillis,
                    routeMillis = Percentiles.of(router.durationsNanos.map { it / 1e6 }),
                    routeComputations = router.durationsNanos.size,
                    doubleAllocations = audit.doubleAllocations,
                    sharedPositions = audit.sharedPositions,
                    lowerBoundSeconds = lowerBound(creations),
                    vehicleSeconds = ledger.totals().mapValues { it.value / 1000.0 },
                    heldBackLines = breakdown?.lines().orEmpty() + patienceLine(scheduler),
                    stalledLines = if (final >= orders) emptyList() else stalledLines(kernel, scheduler),
                )
            }
        }
    }

    private fun report(kernel: SimulationKernel, makespanSeconds: Double, cpuSeconds: Double): SimulationReport {
        val all = kernel.core.orders.all().filter { it.name.startsWith(ORDER_PREFIX) }
        return SimulationReport(
            plant = model.name,
            vehicles = model.vehicles.size,
            clock = if (realTime) "real time, time factor $timeFactor" else "virtual time, time factor $timeFactor",
            ordersCreated = orders,
            ordersFinished = all.count { it.state == TransportOrderState.FINISHED },
            ordersFailed = all.count { it.state == TransportOrderState.FAILED },
            ordersUnroutable = all.count { it.state == TransportOrderState.UNROUTABLE },
            makespanSimulatedSeconds = makespanSeconds,
            kernelCpuSeconds = cpuSeconds,
            deadlocksDetected = kernel.core.watchdog.detected,
            deadlocksResolved = kernel.core.watchdog.resolved,
            idleVehiclesMoved = kernel.core.watchdog.idleVehiclesMoved,
            retreats = kernel.core.watchdog.retreats,
            claimYields = kernel.core.watchdog.claimYields,
            grantsHeldBack = kernel.core.scheduler.grantsHeldBack,
        )
    }

    // Sampling at a fixed kernel period (a twentieth of a watchdog period) changes no decision of the kernel.
    private fun sampleEvery(kernel: SimulationKernel, breakdown: HeldBackBreakdown) {
        kernel.clock.schedule(HELD_BACK_SAMPLE_MILLIS) {
            breakdown.sample(kernel.core.plant.vehicles()) { it.startsWith(ORDER_PREFIX) }
            sampleEvery(kernel, breakdown)
        }
    }

    private fun stalledLines(kernel: SimulationKernel, scheduler: DefaultScheduler?): List<String> =
        stalledVehicleLines(
            kernel.core.plant.vehicles(),
            { vehicle -> scheduler?.grantWaitOf(vehicle)?.first?.label ?: "unknown" },
            kernel.core.scheduler.waitsFor(),
        )

    private fun patienceLine(scheduler: DefaultScheduler?): List<String> =
        listOfNotNull(
            scheduler?.let { "grants_after_park_test_patience: ${it.grantsAfterPatience}" },
            scheduler?.let { "grants_held_back_for_dead_holes: ${it.deadHolesAvoided}" },
        )

    /** The loopback driver's setting [key] as configured, or `null` without the loopback extension. */
    private fun loopbackSetting(key: String): Any? =
        extensions.flatMap { it.settings }.firstOrNull { it.key == key }?.let { config[it] }

    private fun TransportOrderEvent.isSimulationOrderEnding(): Boolean {
        val order = current ?: return false
        return order.name.startsWith(ORDER_PREFIX) && order.state.isFinal && previous?.state?.isFinal == false
    }

    private fun lowerBound(creations: List<TransportOrderCreation>): Double {
        val trips = creations.map { order ->
            val (load, unload) = order.destinations
            Trip(load.target, load.operation, unload.target, unload.operation)
        }
        return LowerBound(model, loopbackSetting("loopback.operatingTime") as Long? ?: 0L)
            .seconds(trips, model.vehicles.size) ?: 0.0
    }

    private fun randomOrder(index: Int): TransportOrderCreation {
        val source = sources.random(random)
        val target = targets.filter { it != source }.random(random)
        return TransportOrderCreation(
            name = "$ORDER_PREFIX%06d".format(index),
            destinations = listOf(Destination(source, loadOperation), Destination(target, unloadOperation)),
        )
    }

    companion object {
        const val ORDER_PREFIX = "Sim-"

        /** A simulated hour without any order ending means the fleet is stuck: stop and report. */
        const val STALL_LIMIT_MILLIS = 3_600_000L

        /** How often the held-back vehicles are sampled, in kernel milliseconds. */
        const val HELD_BACK_SAMPLE_MILLIS = 50L
    }
}

/**
 * The dispatcher's own latency: for each assignment, the time from the moment the order was dispatchable and its
 * vehicle idle (whichever came last) until the order was assigned. Waiting for a busy vehicle is the fleet's delay,
 * not the dispatcher's.
 *
 * The first wave is counted apart: when the whole batch is posted at [postedAt], every idle vehicle and every order
 * are ready at that same moment, and the dispatcher's assignments of that wave follow one another, the last one
 * waiting for all before it. Their latencies measure the dispatcher's throughput ([firstWaveMillis], the time until the
 * wave's last assignment), not how fast it answers a vehicle that becomes free or an order that arrives ([millis]).
 *
 * [waitMillis] is the part of each latency spent before the dispatcher run that made the assignment started
 * ([runStartedAt]: when the run under way started, `null` outside a run), the rest is spent in that run.
 */
private class AssignLatencies(private val kernel: SimulationKernel, private val runStartedAt: () -> Long?) {
    private val dispatchable = HashMap<String, Long>()
    private val idleSince = HashMap<String, Long>()
    private val availability = VehicleAvailability(kernel.core.orders::get, kernel.core.sequences::get)
    val millis = ArrayList<Double>()
    val waitMillis = ArrayList<Double>()
    var postedAt = Long.MIN_VALUE
    var firstWave = 0
        private set
    var firstWaveMillis = 0L
        private set

    fun onEvent(event: KernelEvent) {
        val now = kernel.clock.elapsedMillis()
        if (event is VehicleEvent) {
            val vehicle = event.current ?: return
            val idle = availability.isAvailable(vehicle)
            if (idle && vehicle.name !in idleSince) idleSince[vehicle.name] = now
            if (!idle) idleSince.remove(vehicle.name)
        }
        if (event !is TransportOrderEvent) return
        val order = event.current ?: return
        val before = event.previous?.state
        if (order.state == TransportOrderState.DISPATCHABLE && before != TransportOrderState.DISPATCHABLE) {
            dispatchable[order.name] = now
        }
        if (order.state == TransportOrderState.BEING_PROCESSED && before == TransportOrderState.DISPATCHABLE) {
            val since = dispatchable.remove(order.name) ?: return
            val vehicleIdle = order.processingVehicle?.let { idleSince[it] } ?: since
            val ready = maxOf(since, vehicleIdle)
            if (ready <= postedAt) {
                firstWave++
                firstWaveMillis = maxOf(firstWaveMillis, now - postedAt)
            } else {
                millis += (now - ready).toDouble()
                waitMillis += ((runStartedAt() ?: now) - ready).coerceAtLeast(0).toDouble()
            }
        }
        if (order.state.isFinal) dispatchable.remove(order.name)
    }
}
