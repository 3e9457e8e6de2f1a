package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.AllocationAudit
import org.ktcs.kernel.simulation.SimulationKernel
import kotlin.random.Random

private fun testOrders(kernel: SimulationKernel) = kernel.core.orders.all().filter { it.name.startsWith("T") }

class KernelCoreTest : FunSpec({
    val config = ConfigLoader().load(null, emptyMap(), emptyList())
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }

    fun demoKernel() = SimulationKernel(PlantModelLoader.loadDemo().model, config, listOf(drivers))

    test("an order to a location is carried out by a vehicle and finishes") {
        demoKernel().use { kernel ->
            val creation =
                TransportOrderCreation(
                    "T1",
                    listOf(Destination("Storage 01", "Load cargo"), Destination("Goods out 01", "Unload cargo")),
                )
            kernel.context.execute { kernel.core.createTransportOrder(creation) }
            kernel.context.runUntil {
                kernel.core.orders.get("T1")?.state?.isFinal == true ||
                    kernel.context.elapsedMillis() > 3_600_000
            }

            val order = kernel.core.orders.require("T1")
            order.state shouldBe TransportOrderState.FINISHED
            (order.processingVehicle != null) shouldBe true
        }
    }

    test("500 random orders on the demo plant all finish, and no resource is ever held by two vehicles") {
        demoKernel().use { kernel ->
            val audit = AllocationAudit()
            kernel.core.events.listen(audit::onEvent)
            val random = Random(42)
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
            val oneSimulatedDay = 86_400_000L
            kernel.context.runUntil {
                testOrders(kernel).count { it.state.isFinal } == 500 || kernel.context.elapsedMillis() > oneSimulatedDay
            }

            testOrders(kernel).groupingBy { it.state }.eachCount() shouldBe mapOf(TransportOrderState.FINISHED to 500)
            audit.doubleAllocations shouldBe 0
            audit.sharedPositions shouldBe 0
        }
    }
})
