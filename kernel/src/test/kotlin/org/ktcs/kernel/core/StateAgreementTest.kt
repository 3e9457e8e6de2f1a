package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.error.KernelException
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel
import kotlin.random.Random

/**
 * Facts the kernel keeps in more than one place (which vehicle does which order; which resources a vehicle holds)
 * agree after every step of a random stream of operations: orders, withdrawals, pauses, integration levels and path
 * locks, with the vehicles driving in between.
 */
class StateAgreementTest : FunSpec({
    val config = ConfigLoader().load(null, emptyMap(), emptyList())
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
    val model = PlantModelLoader.loadDemo().model
    val destinations = model.locations.mapNotNull { location ->
        val type = model.locationTypes.firstOrNull { it.name == location.type }
        type?.allowedOperations?.firstOrNull()?.let { Destination(location.name, it) }
    }
    val vehicles = model.vehicles.map { it.name }
    val paths = model.paths.map { it.name }
    val steps = 150

    fun SimulationKernel.step(action: KernelCore.() -> Unit) {
        var done = false
        context.execute {
            try {
                core.action()
            } catch (refused: KernelException) {
                // A refusal (e.g. a withdrawal of a final order) is an answer, not a failure: the state is unchanged.
            }
            done = true
        }
        context.runUntil { done }
    }

    fun KernelCore.randomOperation(random: Random, created: Int) {
        val vehicle = vehicles.random(random)
        val open = orders.all().filter { !it.state.isFinal }
        when (random.nextInt(10)) {
            in 0..3 -> createTransportOrder(
                TransportOrderCreation(
                    "T-$created",
                    List(random.nextInt(1, 3)) { destinations.random(random) },
                    intendedVehicle = vehicle.takeIf { random.nextBoolean() },
                ),
            )

            4 -> open.randomOrNull(random)?.let { withdraw(it.name, immediate = random.nextBoolean(), false) }

            5 -> requests.setPaused(vehicle, !plant.vehicle(vehicle).paused)

            6 -> requests.setIntegrationLevel(vehicle, IntegrationLevel.entries.random(random))

            7 -> requests.withdrawByVehicle(vehicle, immediate = random.nextBoolean(), disableVehicle = false)

            8 -> setPathLocked(paths.random(random), random.nextInt(4) == 0)

            else -> Unit
        }
    }

    test("the copies of 'which vehicle does this order' and 'which resources it holds' agree after every step") {
        for (seed in 1..3) {
            val random = Random(seed)
            SimulationKernel(model, config, listOf(drivers)).use { kernel ->
                val disagreements = mutableListOf<String>()
                var processed = 0
                repeat(steps) { index ->
                    kernel.step { randomOperation(random, index) }
                    kernel.context.runUntilTime(kernel.context.elapsedMillis() + random.nextLong(100, 20_000))
                    kernel.step {
                        disagreements += disagreements().map { "seed $seed, step $index: $it" }
                        processed = orders.all().count { it.state == TransportOrderState.FINISHED }
                    }
                }
                disagreements.joinToString("\n") shouldBe ""
                processed shouldBeGreaterThan 0
            }
        }
    }
})
