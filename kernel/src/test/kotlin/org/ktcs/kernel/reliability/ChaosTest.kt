package org.ktcs.kernel.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.runBlocking
import org.ktcs.api.error.KernelException
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.simulation.SimulationKernel
import kotlin.random.Random

/**
 * Issue #14's chaos run, on virtual time: 300 orders while random, seeded operator actions (withdrawals, path locks,
 * pauses, integration levels) hit the fleet through the kernel's public services. After every vehicle event no
 * resource may be held by two vehicles and no two vehicles the kernel respects may stand on one point; once the
 * actions stop and the operator puts everything back, every order that was not withdrawn finishes.
 */
class ChaosTest : FunSpec({
    test("$ORDERS orders under random operator actions: nothing held twice, and the rest finish afterwards") {
        demoKernel().use { kernel ->
            val run = ChaosRun(kernel, Random(SEED))
            run.start()
            kernel.context.runUntil { (run.created >= ORDERS && run.openOrders() == 0) || run.stuck() }
            println("chaos (seed $SEED): ${run.summary()}")
            run.violations.take(10).forEach { println("chaos violation: $it") }
            run.unfinished().take(10).forEach { println("chaos unfinished: $it") }

            run.violations.shouldBeEmpty()
            run.unfinished().shouldBeEmpty()
            run.created shouldBe ORDERS
        }
    }
}) {
    companion object {
        val SEED = System.getProperty("ktcs.chaos.seed")?.toLong() ?: 14L
        const val ORDERS = 300
    }
}

private class ChaosRun(private val kernel: SimulationKernel, private val random: Random) {
    private val services: KernelServices = kernel.services
    private val vehicles = kernel.core.plant.vehicles().map { it.name }
    private val paths = kernel.core.plant.staticModel().paths.map { it.name }
    private val sources = listOf("Storage 01", "Storage 02", "Goods in north 01", "Goods in south 01")
    private val targets = listOf("Goods out 01", "Goods out 02", "Storage 01", "Storage 02")
    private val withdrawn = HashSet<String>()
    private val actions = sortedMapOf<String, Int>()
    private val refused = sortedMapOf<String, Int>()
    private var actionsStopped = false
    private var lastProgress = 0L
    private var eventsChecked = 0
    val violations = mutableListOf<String>()
    var created = 0
        private set

    fun start() {
        kernel.core.events.listen { event ->
            if (event is VehicleEvent) check(event)
            val order = (event as? org.ktcs.api.event.TransportOrderEvent)?.current
            if (order != null && order.state.isFinal && event.previous?.state?.isFinal == false) {
                lastProgress = kernel.context.elapsedMillis()
                kernel.context.execute(::createNext)
            }
        }
        kernel.context.execute { repeat(OPEN_ORDERS) { createNext() } }
        scheduleAction()
    }

    fun openOrders(): Int = kernel.core.orders.all().count { !it.state.isFinal }

    fun stuck(): Boolean = kernel.context.elapsedMillis() - lastProgress > STALL_MILLIS

    fun unfinished(): List<String> = kernel.core.orders.all()
        .filter { it.name.startsWith(PREFIX) && it.name !in withdrawn && it.state != TransportOrderState.FINISHED }
        .map { "${it.name} ${it.state} vehicle=${it.processingVehicle}" }

    private fun finished(): Int =
        kernel.core.orders.all().count { it.name.startsWith(PREFIX) && it.state == TransportOrderState.FINISHED }

    fun summary(): String = "orders created $created, finished ${finished()}, " +
        "withdrawn ${withdrawn.size}, actions $actions (refused $refused), vehicle events checked $eventsChecked, " +
        "violations ${violations.size}, simulated ${kernel.context.elapsedMillis() / 1000} s"

    /** After every vehicle event: each resource has one holder, and respected vehicles stand on distinct points. */
    private fun check(event: VehicleEvent) {
        eventsChecked++
        val all = kernel.core.plant.vehicles()
        val holders = all.flatMap { v -> v.allocatedResources.flatten().toSet().map { it to v.name } }
            .groupBy({ it.first }, { it.second }).filterValues { it.size > 1 }
        val shared = all.filter {
            it.integrationLevel >= IntegrationLevel.TO_BE_RESPECTED && it.currentPosition != null
        }
            .groupBy({ it.currentPosition!! }, { it.name }).filterValues { it.size > 1 }
        if (holders.isNotEmpty() || shared.isNotEmpty()) {
            violations +=
                "t=${kernel.context.elapsedMillis()} after ${event.current?.name}: held twice $holders, shared $shared"
        }
    }

    private fun createNext() {
        if (created >= ChaosTest.ORDERS) return
        val source = sources.random(random)
        val target = targets.filter { it != source }.random(random)
        val name = "$PREFIX%03d".format(created++)
        service {
            transportOrders.createTransportOrder(
                TransportOrderCreation(
                    name,
                    listOf(Destination(source, "Load cargo"), Destination(target, "Unload cargo")),
                ),
            )
        }
    }

    private fun scheduleAction() {
        kernel.context.schedule(random.nextLong(10_000, 90_000)) {
            if (created >= ChaosTest.ORDERS - OPEN_ORDERS || actions.values.sum() >= MAX_ACTIONS) {
                return@schedule restoreEverything()
            }
            act()
            scheduleAction()
        }
    }

    private fun act() {
        val vehicle = vehicles.random(random)
        when (random.nextInt(20)) {
            0 -> record("withdraw order regularly") { withdrawOrder(immediate = false) }

            1 -> record("withdraw order immediately") { withdrawOrder(immediate = true) }

            2 -> record("withdraw by vehicle") {
                kernel.core.plant.vehicle(vehicle).transportOrder?.let { withdrawn += it }
                dispatcher.withdrawByVehicle(vehicle, immediate = random.nextBoolean())
            }

            in 3..5 -> record("lock path") { plantModel.setPathLocked(paths.random(random), true) }

            in 6..8 -> record("unlock path") { plantModel.setPathLocked(paths.random(random), false) }

            in 9..12 -> record("pause") { vehicles.setPaused(vehicle, random.nextBoolean()) }

            else -> record("integration level") {
                // Half the time back to work, so that the fleet keeps moving between the disruptions.
                val level = when (random.nextInt(10)) {
                    in 0..3 -> IntegrationLevel.TO_BE_UTILIZED
                    in 4..6 -> IntegrationLevel.TO_BE_IGNORED
                    else -> IntegrationLevel.entries.random(random)
                }
                vehicles.setIntegrationLevel(vehicle, level)
            }
        }
    }

    private suspend fun KernelServices.withdrawOrder(immediate: Boolean) {
        val open = kernel.core.orders.all().filter { !it.state.isFinal }
        if (open.isEmpty()) return
        val order = open.random(random).name
        withdrawn += order
        dispatcher.withdrawByTransportOrder(order, immediate)
    }

    /** The operator puts everything back: no locks, no pauses, every vehicle utilized (retried while refused). */
    private fun restoreEverything() {
        actionsStopped = true
        paths.forEach { path -> service { plantModel.setPathLocked(path, false) } }
        vehicles.forEach { vehicle -> service { vehicles.setPaused(vehicle, false) } }
        val refusedAgain = vehicles.filter { vehicle ->
            kernel.core.plant.vehicle(vehicle).integrationLevel != IntegrationLevel.TO_BE_UTILIZED &&
                !service { vehicles.setIntegrationLevel(vehicle, IntegrationLevel.TO_BE_UTILIZED) }
        }
        if (refusedAgain.isNotEmpty()) kernel.context.schedule(RETRY_MILLIS, ::restoreEverything)
    }

    private fun record(kind: String, action: suspend KernelServices.() -> Unit) {
        actions.merge(kind, 1, Int::plus)
        if (!service(action)) refused.merge(kind, 1, Int::plus)
    }

    /** Runs [action] in the kernel context (services answer there at once); `false` if the kernel refused it. */
    private fun service(action: suspend KernelServices.() -> Unit): Boolean = try {
        runBlocking { services.action() }
        true
    } catch (_: KernelException) {
        false
    }

    private companion object {
        const val OPEN_ORDERS = 6
        const val PREFIX = "Chaos-"
        const val MAX_ACTIONS = 400
        const val RETRY_MILLIS = 5_000L
        const val STALL_MILLIS = 4 * 3_600_000L
    }
}
