package org.ktcs.kernel.simulation

import org.koin.dsl.module
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.ProcState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.routing.Router
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.extension.KtcsExtension
import org.ktcs.kernel.routerConfiguration
import org.ktcs.kernel.routing.DefaultRouter
import java.lang.management.ManagementFactory
import kotlin.random.Random

/**
 * Runs the kernel with loopback vehicles on random transport orders (load at one station, unload at another) on
 * virtual time, and measures it. Keeps as many orders open as there are vehicles, creating the next whenever one
 * ends, until [orders] were created and all are final (or [limitSimulatedMillis] passed).
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
) {
    private val random = Random(seed)
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
        val overrides = module { single<Router> { router } }
        SimulationKernel(model, config, extensions.map { it.module() } + overrides).use { kernel ->
            val audit = AllocationAudit()
            val latencies = AssignLatencies(kernel)
            var created = 0
            var final = 0
            var lastProgress = 0L
            fun createNext() {
                if (created >= orders) return
                kernel.core.createTransportOrder(randomOrder(created++))
            }
            kernel.core.events.listen(audit::onEvent)
            kernel.core.events.listen(latencies::onEvent)
            kernel.core.events.listen { event ->
                if (event is TransportOrderEvent && event.isSimulationOrderEnding()) {
                    final++
                    lastProgress = kernel.context.elapsedMillis()
                    kernel.context.execute(::createNext)
                }
            }
            val threads = ManagementFactory.getThreadMXBean()
            val cpuStart = threads.currentThreadCpuTime
            val wallStart = System.nanoTime()
            kernel.context.execute { repeat(model.vehicles.size) { createNext() } }
            val stalled = { kernel.context.elapsedMillis() - lastProgress > STALL_LIMIT_MILLIS }
            kernel.context.runUntil {
                final >= orders || stalled() ||
                    kernel.context.elapsedMillis() > limitSimulatedMillis
            }
            if (System.getProperty("ktcs.safetyDebug") != null) {
                kernel.core.plant.vehicles().forEach { v ->
                    System.err.println("${v.name} ${v.state} ${v.procState} ${v.currentPosition} order=${v.transportOrder} alloc=${v.allocatedResources} claimed=${v.claimedResources.size} pending=${kernel.core.scheduler.pendingAllocations()[v.name]}")
                }
            }
            val makespan = kernel.context.elapsedMillis() / 1000.0
            val all = kernel.core.orders.all().filter { it.name.startsWith(ORDER_PREFIX) }
            return SimulationReport(
                plant = model.name,
                vehicles = model.vehicles.size,
                ordersCreated = created,
                ordersFinished = all.count { it.state == TransportOrderState.FINISHED },
                ordersFailed = all.count {
                    it.state == TransportOrderState.FAILED ||
                        it.state == TransportOrderState.UNROUTABLE
                },
                makespanSimulatedSeconds = makespan,
                kernelCpuSeconds = (threads.currentThreadCpuTime - cpuStart) / 1e9,
                wallSeconds = (System.nanoTime() - wallStart) / 1e9,
                assignLatencyMillis = Percentiles.of(latencies.millis),
                routeMillis = Percentiles.of(router.durationsNanos.map { it / 1e6 }),
                routeComputations = router.durationsNanos.size,
                deadlocksDetected = kernel.core.watchdog.detected,
                deadlocksResolved = kernel.core.watchdog.resolved,
                idleVehiclesMoved = kernel.core.watchdog.idleVehiclesMoved,
                doubleAllocations = audit.doubleAllocations,
                sharedPositions = audit.sharedPositions,
            )
        }
    }

    private fun TransportOrderEvent.isSimulationOrderEnding(): Boolean {
        val order = current ?: return false
        return order.name.startsWith(ORDER_PREFIX) && order.state.isFinal && previous?.state?.isFinal == false
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
    }
}

/**
 * How long orders wait between becoming DISPATCHABLE and being assigned, counting only orders that went to a vehicle
 * which was already idle when the order became dispatchable: the dispatcher's own latency, not the fleet's (an order
 * that waits for a busy or recharging vehicle is not the dispatcher's delay).
 */
private class AssignLatencies(private val kernel: SimulationKernel) {
    private class Waiting(val sinceMillis: Long, val idleVehicles: Set<String>)

    private val waiting = HashMap<String, Waiting>()
    val millis = ArrayList<Double>()

    fun onEvent(event: KernelEvent) {
        if (event !is TransportOrderEvent) return
        val order = event.current ?: return
        val before = event.previous?.state
        if (order.state == TransportOrderState.DISPATCHABLE && before != TransportOrderState.DISPATCHABLE) {
            waiting[order.name] = Waiting(kernel.context.elapsedMillis(), idleVehicles())
        }
        if (order.state == TransportOrderState.BEING_PROCESSED && before == TransportOrderState.DISPATCHABLE) {
            val wait = waiting.remove(order.name) ?: return
            if (order.processingVehicle in
                wait.idleVehicles
            ) {
                millis += (kernel.context.elapsedMillis() - wait.sinceMillis).toDouble()
            }
        }
        if (order.state.isFinal) waiting.remove(order.name)
    }

    private fun idleVehicles(): Set<String> = kernel.core.plant.vehicles()
        .filter {
            it.integrationLevel == IntegrationLevel.TO_BE_UTILIZED && it.procState == ProcState.IDLE &&
                it.transportOrder == null
        }
        .mapTo(HashSet()) { it.name }
}
