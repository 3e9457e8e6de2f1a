package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.simulation.SimulationKernel
import org.ktcs.kernel.web.v1.orders.toDto

/** A vehicle left loaded by an order withdrawn between load and unload: the operator is told, and it says why it waits. */
class LoadedVehicleTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("loopback.positionReportInterval=0", "dispatcher.parkIdleVehicles=false"),
    )

    fun SimulationKernel.now(action: KernelCore.() -> Unit) = execute(settleMillis = 100, action)

    fun trip(name: String, from: String, to: String) = TransportOrderCreation(
        name,
        listOf(Destination(from, "Load cargo"), Destination(to, "Unload cargo")),
        intendedVehicle = "Vehicle-01",
    )

    test("the operator is told, the vehicle and the order say why, and a load reset lets it work again") {
        SimulationKernel(
            PlantModelLoader.loadDemo().model,
            config,
            listOf(LoopbackExtension().module()),
        ).use { kernel ->
            val vehicle = { kernel.core.plant.vehicle("Vehicle-01") }
            kernel.now { kernel.core.createTransportOrder(trip("First", "Goods in north 01", "Goods out 02")) }
            kernel.context.runUntil { vehicle().loadHandlingDevices.any { it.full } }
            kernel.now { kernel.core.withdraw("First", immediate = true, disableVehicle = false) }

            kernel.core.notifications.recent().last().text shouldContain
                "vehicle Vehicle-01 still carries a load after its order First ended unfinished"

            kernel.now { kernel.core.createTransportOrder(trip("Second", "Storage 01", "Goods out 01")) }
            kernel.core.orders.require("Second").state shouldBe TransportOrderState.DISPATCHABLE
            vehicle().waitingReason shouldBe "refuses the waiting orders: driver refused: cannotLoadWhenLoaded"
            kernel.core.orders.require("Second").toDto().waitingReason shouldBe
                "vehicle Vehicle-01: driver refused: cannotLoadWhenLoaded"

            val reset = DriverMessage(LoopbackMessages.SET_LOADED, mapOf("value" to "false"))
            kernel.now { kernel.core.requests.sendDriverMessage("Vehicle-01", reset) }
            kernel.core.orders.require("Second").state shouldBe TransportOrderState.BEING_PROCESSED
            vehicle().waitingReason shouldBe null
        }
    }
})
