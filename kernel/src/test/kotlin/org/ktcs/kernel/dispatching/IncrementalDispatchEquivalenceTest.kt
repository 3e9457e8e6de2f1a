package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderState
import kotlin.random.Random

/**
 * A run on changes (only the new orders, while no vehicle can take a waiting one) must decide exactly what a full run
 * decides. Two kernels get the same random stream of new orders and vehicle events; one dispatcher runs on changes,
 * the other always in full, and after every run both have made the same assignments, created the same orders and
 * given every order and vehicle the same waiting reason.
 */
class IncrementalDispatchEquivalenceTest : FunSpec({
    val points = listOf("A", "B", "C", "D", "E", "F", "G", "H")
    val configurations = mapOf(
        "assignment only" to assignOnly,
        "parking and recharging" to DispatcherConfiguration(),
        "vehicles choose by energy" to assignOnly.copy(
            vehiclePriorities = listOf(VehiclePriority.BY_ENERGY_LEVEL),
            orderCandidatePriorities = listOf(CandidatePriority.BY_COMPLETE_ROUTING_COSTS),
        ),
        // Pass-over counts carry from run to run: a run on changes must count what a full run counts.
        "nearest order within a window of 2" to assignOnly.copy(orderCandidateWindow = 2),
        "openTCS's choice among all orders" to assignOnly.copy(
            orderCandidatePriorities = listOf(CandidatePriority.BY_DEADLINE),
            orderCandidateWindow = 0,
        ),
    )

    /** Both kernels, fed the same events. */
    class Twins(configuration: DispatcherConfiguration, seed: Int) {
        private val model = plant(charger("Charger", "A"), park = setOf("A", "H"))
        val incremental = FakeDispatchContext(model)
        val full = FakeDispatchContext(model)
        val onChanges = incremental.dispatcher(configuration)
        private val always = full.dispatcher(configuration)
        private val random = Random(seed)
        private val newOrders = mutableListOf<String>()
        private var fullRunDue = false
        private var seen = 0
        private var ordersMade = 0

        init {
            // Some drivers refuse some orders, so refusals and their reasons are part of the comparison.
            val driver = { vehicle: String, order: org.ktcs.api.order.TransportOrder ->
                if ((vehicle + order.name).hashCode() % 7 == 0) Explained.no("cannot reach") else Explained.YES
            }
            incremental.driver = driver
            full.driver = driver
            (1..4).forEach { both(vehicle("V$it", at = points[random.nextInt(points.size)])) }
        }

        private fun both(vararg objects: Any) {
            incremental.add(*objects)
            full.add(*objects)
        }

        fun step() {
            when (random.nextInt(10)) {
                in 0..4 -> newOrder()
                in 5..6 -> finishSomeOrder()
                7 -> changeEnergyOfSomeVehicle()
                8 -> pauseOrResumeSomeVehicle()
                else -> fullRunDue = true
            }
            if (random.nextInt(3) == 0) return // Events pile up between runs, as within a coalescing delay.
            if (fullRunDue) onChanges.dispatch() else onChanges.dispatchChanges(newOrders.toList())
            always.dispatch()
            fullRunDue = false
            newOrders.clear()
            // Orders the dispatcher created (to park or recharge) became dispatchable: the kernel reports them as new.
            newOrders += incremental.created.drop(seen).map { it.name }
            seen = incremental.created.size
        }

        private fun newOrder() {
            val name = "T${++ordersMade}"
            val destination = when (random.nextInt(4)) {
                0 -> moveTo(points[random.nextInt(points.size)])
                1 -> Destination("S1", "LOAD")
                else -> Destination("S2", if (random.nextBoolean()) "LOAD" else "UNLOAD")
            }
            val intended = when (random.nextInt(10)) {
                0, 1 -> "V${1 + random.nextInt(4)}"
                2 -> "V9"
                else -> null
            }
            val created = T0.plusSeconds(random.nextLong(100))
            val deadline = if (random.nextBoolean()) {
                created.plusSeconds(
                    random.nextLong(3600),
                )
            } else {
                java.time.Instant.MAX
            }
            both(order(name, destination, created = created, deadline = deadline, intended = intended))
            newOrders += name
        }

        private fun finishSomeOrder() {
            val busy = incremental.vehicles.values.filter { it.transportOrder != null }.randomOrNull(random) ?: return
            val order = incremental.orders.getValue(busy.transportOrder!!)
            val end = order.driveOrders.last().route?.finalDestinationPoint ?: busy.currentPosition
            both(
                order.copy(state = TransportOrderState.FINISHED),
                busy.copy(transportOrder = null, procState = ProcState.IDLE, currentPosition = end),
            )
        }

        private fun changeEnergyOfSomeVehicle() {
            val vehicle = incremental.vehicles.values.random(random)
            both(vehicle.copy(energyLevel = listOf(5, 40, 100).random(random)))
        }

        private fun pauseOrResumeSomeVehicle() {
            val vehicle = incremental.vehicles.values.random(random)
            val change = random.nextInt(3)
            both(
                when (change) {
                    0 -> vehicle.copy(paused = !vehicle.paused)

                    1 -> vehicle.copy(
                        state = if (vehicle.state == VehicleState.IDLE) VehicleState.ERROR else VehicleState.IDLE,
                    )

                    else -> vehicle.copy(
                        integrationLevel = if (vehicle.integrationLevel == IntegrationLevel.TO_BE_UTILIZED) {
                            IntegrationLevel.TO_BE_RESPECTED
                        } else {
                            IntegrationLevel.TO_BE_UTILIZED
                        },
                    )
                },
            )
        }
    }

    fun FakeDispatchContext.lastReasons(): Map<String, String> = deferrals.associate { it }

    configurations.forEach { (label, configuration) ->
        test("runs on changes decide what full runs decide: $label") {
            var onChanges = 0
            (1..12).forEach { seed ->
                val twins = Twins(configuration, seed)
                repeat(150) { step ->
                    twins.step()
                    val context = "seed $seed, step $step"
                    withClue(context) {
                        twins.incremental.assignments shouldBe twins.full.assignments
                        twins.incremental.created.map { it.name } shouldBe twins.full.created.map { it.name }
                        twins.incremental.lastReasons() shouldBe twins.full.lastReasons()
                        twins.incremental.vehicleReasons shouldBe twins.full.vehicleReasons
                    }
                }
                onChanges += twins.onChanges.incrementalRuns
            }
            // The comparison means something only if runs on changes did take the short way.
            onChanges shouldBeGreaterThan 100
        }
    }

    test("while no vehicle can take an order, a run on changes does not read the waiting orders") {
        val context = FakeDispatchContext(plant())
        val dispatcher = context.dispatcher()
        context.busy("V1")
        context.add(*(1..100).map { order("T$it") }.toTypedArray())
        dispatcher.dispatch()
        val reads = context.dispatchableReads

        context.add(order("T101"))
        dispatcher.dispatchChanges(listOf("T101"))

        context.dispatchableReads shouldBe reads
        context.deferralsOf("T101") shouldBe listOf("every vehicle is busy with an order: V1")
        dispatcher.incrementalRuns shouldBe 1
    }

    test("a freed vehicle takes the oldest waiting order, the others keep their reason, new ones are looked at alone") {
        val context = FakeDispatchContext(plant())
        val dispatcher = context.dispatcher()
        context.busy("V1", "V2")
        context.add(*(1..20).map { order("T$it", created = T0.plusSeconds(it.toLong())) }.toTypedArray())
        dispatcher.dispatch()

        context.add(vehicle("V2", at = "D"), order("Busy-V2", state = TransportOrderState.FINISHED))
        dispatcher.dispatchChanges(emptyList())

        context.assignedOrder("V2") shouldBe "T1"
        context.deferralsOf("T2") shouldBe listOf("every vehicle is busy with an order: V1, V2")
        val reads = context.dispatchableReads

        context.add(order("T21", created = T0.plusSeconds(21)))
        dispatcher.dispatchChanges(listOf("T21"))

        dispatcher.incrementalRuns shouldBe 2
        context.dispatchableReads shouldBe reads
        context.deferralsOf("T21") shouldBe listOf("every vehicle is busy with an order: V1, V2")
    }
})

/** Vehicles each busy with an order of its own (`Busy-V1` …). */
private fun FakeDispatchContext.busy(vararg vehicles: String) = vehicles.forEach {
    add(vehicle(it).processing("Busy-$it"), order("Busy-$it", state = TransportOrderState.BEING_PROCESSED))
}

private inline fun <T> withClue(clue: String, block: () -> T): T = io.kotest.assertions.withClue(clue, block)
