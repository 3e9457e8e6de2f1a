package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.ints.shouldBeGreaterThanOrEqual
import io.kotest.matchers.shouldBe
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel
import kotlin.random.Random

/** The kernel with four loopback vehicles on the demo plant, on virtual time. */
class KernelWithLoopbackTest : FunSpec({
    test(
        "500 random transport orders all finish; after every event no resource has two holders and no point two vehicles",
    ) {
        val config = ConfigLoader().load(null, emptyMap(), listOf("loopback.positionReportInterval=0"))
        SimulationKernel(
            PlantModelLoader.loadDemo().model,
            config,
            listOf(LoopbackExtension().module()),
        ).use { kernel ->
            val violations = mutableListOf<String>()
            kernel.core.events.listen { violations += exclusivityViolations(kernel) }
            val random = Random(7)
            val stations = kernel.core.plant.model().locations.filter { it.type == "Transfer station" }.map { it.name }
            repeat(500) { index ->
                val (from, to) = stations.shuffled(random).take(2)
                val creation =
                    TransportOrderCreation(
                        "T$index",
                        listOf(Destination(from, "Load cargo"), Destination(to, "Unload cargo")),
                    )
                kernel.context.execute { kernel.core.createTransportOrder(creation) }
            }
            val testOrders = { kernel.core.orders.all().filter { it.name.startsWith("T") } }
            val twoSimulatedDays = 2 * 86_400_000L
            kernel.context.runUntil {
                testOrders().count { it.state.isFinal } == 500 ||
                    kernel.context.elapsedMillis() > twoSimulatedDays
            }

            testOrders().groupingBy { it.state }.eachCount() shouldBe mapOf(TransportOrderState.FINISHED to 500)
            violations.shouldBeEmpty()
        }
    }

    test("a vehicle whose energy drains while driving is sent to recharge and charges again") {
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf(
                "loopback.positionReportInterval=0",
                "loopback.energyDrainPercentPerKm=300",
                "loopback.rechargePercentPerSecond=5",
            ),
        )
        SimulationKernel(
            PlantModelLoader.loadDemo().model,
            config,
            listOf(LoopbackExtension().module()),
        ).use { kernel ->
            var lowest = 100
            var highestAfterLow = 0
            kernel.core.events.listen { event ->
                val vehicle = (event as? VehicleEvent)?.current?.takeIf { it.name == "Vehicle-01" } ?: return@listen
                lowest = minOf(lowest, vehicle.energyLevel)
                if (lowest < 90) highestAfterLow = maxOf(highestAfterLow, vehicle.energyLevel)
            }
            val trip =
                listOf(Destination("Goods in north 01", "Load cargo"), Destination("Goods out 02", "Unload cargo"))
            kernel.context.execute {
                kernel.core.createTransportOrder(TransportOrderCreation("Trip", trip, intendedVehicle = "Vehicle-01"))
            }
            kernel.context.runUntil { highestAfterLow >= 95 || kernel.context.elapsedMillis() > 3_600_000 }

            kernel.core.orders.require("Trip").state shouldBe TransportOrderState.FINISHED
            (lowest < 90) shouldBe true
            val recharge = kernel.core.orders.all().single {
                it.name.startsWith("Recharge-") &&
                    it.intendedVehicle == "Vehicle-01"
            }
            recharge.driveOrders.single().destination.operation shouldBe "CHARGE"
            highestAfterLow shouldBeGreaterThanOrEqual 95
        }
    }
})

/** Checks the whole fleet after any kernel event: the invariant is asserted from the state, not assumed. */
private fun exclusivityViolations(kernel: SimulationKernel): List<String> {
    val vehicles = kernel.core.plant.vehicles()
    val holders = vehicles.flatMap { vehicle ->
        vehicle.allocatedResources.flatten().toSet().map { it to vehicle.name }
    }
    val shared = holders.groupBy({
        it.first
    }, { it.second }).filterValues { it.size > 1 }.map { (resource, names) -> "$resource held by $names" }
    val stacked = vehicles.mapNotNull { it.currentPosition?.let { point -> point to it.name } }
        .groupBy({
            it.first
        }, { it.second }).filterValues { it.size > 1 }.map { (point, names) -> "$point occupied by $names" }
    return shared + stacked
}
