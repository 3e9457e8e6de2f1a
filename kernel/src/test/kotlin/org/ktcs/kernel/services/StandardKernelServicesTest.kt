package org.ktcs.kernel.services

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.runBlocking
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.simulation.SimulationKernel

/** The services, called as the web API will call them: suspending, from outside the kernel context. */
class StandardKernelServicesTest : FunSpec({
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }

    fun kernel(vararg settings: String) = SimulationKernel(
        PlantModelLoader.loadDemo().model,
        ConfigLoader().load(null, emptyMap(), listOf("dispatcher.parkIdleVehicles=false") + settings),
        listOf(drivers),
    )

    /**
     * Calls the services as a client outside the kernel context would, then runs the kernel until the answer is
     * there. Unconfined: the caller resumes inside the kernel task that answers it, so virtual time cannot run ahead
     * while a second thread catches up.
     */
    fun <T> SimulationKernel.serve(block: suspend KernelServices.() -> T): T {
        val result = CoroutineScope(Dispatchers.Unconfined).async { services.block() }
        context.runUntil { result.isCompleted }
        return runBlocking { result.await() }
    }

    val trip = listOf(Destination("Storage 01", "Load cargo"), Destination("Goods out 01", "Unload cargo"))

    test("an order created through the service is processed; unknown names are null or ObjectUnknown") {
        kernel().use { kernel ->
            val created = kernel.serve { transportOrders.createTransportOrder(TransportOrderCreation("T", trip)) }
            created.state shouldBe TransportOrderState.DISPATCHABLE
            kernel.serve { transportOrders.transportOrder("nope") }.shouldBeNull()
            shouldThrow<ObjectUnknownException> {
                kernel.serve { dispatcher.withdrawByTransportOrder("nope", immediate = false) }
            }
                .message shouldBe "unknown transport order 'nope'"
        }
    }

    test("the intended vehicle can change before assignment, not after") {
        kernel("kernel.initialIntegrationLevel=TO_BE_RESPECTED").use { kernel ->
            kernel.serve { transportOrders.createTransportOrder(TransportOrderCreation("T", trip)) }
            kernel.serve { transportOrders.setIntendedVehicle("T", "Vehicle-03") }
            kernel.serve { transportOrders.transportOrder("T") }!!.intendedVehicle shouldBe "Vehicle-03"
            shouldThrow<ObjectUnknownException> { kernel.serve { transportOrders.setIntendedVehicle("T", "Ghost") } }

            kernel.serve {
                vehicles.setIntegrationLevel("Vehicle-03", org.ktcs.api.model.IntegrationLevel.TO_BE_UTILIZED)
            }
            kernel.context.runUntil { kernel.core.orders.require("T").state == TransportOrderState.BEING_PROCESSED }
            shouldThrow<IllegalStateChangeException> {
                kernel.serve { transportOrders.setIntendedVehicle("T", "Vehicle-01") }
            }
        }
    }

    test("immediate assignment gives a dispatchable order to its idle intended vehicle, and explains a refusal") {
        kernel("kernel.initialIntegrationLevel=TO_BE_RESPECTED").use { kernel ->
            kernel.serve {
                transportOrders.createTransportOrder(TransportOrderCreation("T", trip, intendedVehicle = "Vehicle-02"))
            }
            shouldThrow<IllegalStateChangeException> { kernel.serve { dispatcher.assignNow("T") } }.message shouldBe
                "cannot assign 'T' to vehicle 'Vehicle-02' now: integration level TO_BE_RESPECTED"

            kernel.serve {
                vehicles.setIntegrationLevel("Vehicle-02", org.ktcs.api.model.IntegrationLevel.TO_BE_UTILIZED)
            }
            kernel.context.runUntil { kernel.core.orders.require("T").state != TransportOrderState.DISPATCHABLE }
            kernel.core.orders.require("T").processingVehicle shouldBe "Vehicle-02"
        }
    }

    // assignNow once checked less than the dispatcher: a paused vehicle, or one refusing the type, got the order.
    test("immediate assignment refuses what the dispatcher refuses: a paused vehicle, a type it does not accept") {
        kernel().use { kernel ->
            kernel.serve {
                vehicles.setPaused("Vehicle-02", true)
                vehicles.setAllowedOrderTypes("Vehicle-03", setOf("Transport"))
                transportOrders.createTransportOrder(TransportOrderCreation("P", trip, intendedVehicle = "Vehicle-02"))
                transportOrders.createTransportOrder(
                    TransportOrderCreation("S", trip, type = "Special", intendedVehicle = "Vehicle-03"),
                )
            }

            shouldThrow<IllegalStateChangeException> { kernel.serve { dispatcher.assignNow("P") } }.message shouldBe
                "cannot assign 'P' to vehicle 'Vehicle-02' now: paused"
            shouldThrow<IllegalStateChangeException> { kernel.serve { dispatcher.assignNow("S") } }.message shouldBe
                "cannot assign 'S' to vehicle 'Vehicle-03' now: does not accept type 'Special'"
            kernel.core.orders.require("P").state shouldBe TransportOrderState.DISPATCHABLE
            kernel.core.orders.require("S").state shouldBe TransportOrderState.DISPATCHABLE
        }
    }

    test("energy thresholds are checked before they are set") {
        kernel().use { kernel ->
            shouldThrow<InvalidRequestException> {
                kernel.serve {
                    vehicles.setEnergyLevelThresholdSet("Vehicle-01", EnergyLevelThresholdSet(critical = 95, good = 90))
                }
            }.message shouldBe "vehicle 'Vehicle-01': critical 95 is above good 90"
            kernel.serve { vehicles.setEnergyLevelThresholdSet("Vehicle-01", EnergyLevelThresholdSet(20, 80, 40, 95)) }
            kernel.serve { vehicles.vehicle("Vehicle-01") }!!.energyLevelThresholdSet shouldBe
                EnergyLevelThresholdSet(20, 80, 40, 95)
        }
    }

    test("route queries answer per destination point and reject unknown points") {
        kernel().use { kernel ->
            val routes = kernel.serve { router.computeRoutes("Vehicle-01", null, listOf("Point-0028", "Point-0002")) }
            routes.getValue("Point-0028").single().finalDestinationPoint shouldBe "Point-0028"
            shouldThrow<ObjectUnknownException> {
                kernel.serve { router.computeRoutes("Vehicle-01", null, listOf("Nowhere")) }
            }
                .message shouldBe "unknown point 'Nowhere'"
        }
    }

    test("old final orders are swept out after the configured age") {
        kernel("orderpool.sweepInterval=60000", "orderpool.sweepAge=600000").use { kernel ->
            kernel.serve { transportOrders.createTransportOrder(TransportOrderCreation("T", trip)) }
            kernel.context.runUntil { kernel.core.orders.require("T").state.isFinal }
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 700_000)
            kernel.serve { transportOrders.transportOrders() }.filter { it.name == "T" }.shouldBeEmpty()
        }
    }
})
