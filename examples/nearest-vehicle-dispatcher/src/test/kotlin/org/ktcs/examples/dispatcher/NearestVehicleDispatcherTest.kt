package org.ktcs.examples.dispatcher

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.types.shouldBeInstanceOf
import org.koin.core.module.Module
import org.ktcs.adapters.loopback.LoopbackExtension
import org.ktcs.api.model.PlantModel
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.extension.Extensions
import org.ktcs.kernel.simulation.SimulationKernel

/**
 * The demo plant where the vehicle nearest to "Storage 01" has the least energy: kTCS's default dispatcher prefers
 * energy and gives the order to another vehicle; the replacement, swapped in by its extension, gives it to the
 * nearest.
 */
class NearestVehicleDispatcherTest : FunSpec({
    // Parking and recharging off: the vehicles stay where they are until the order comes.
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
    )
    val demo = PlantModelLoader.loadDemo().model
    val nearest = nearestVehicleTo(demo, "Point-0028", config)
    val plant = demo.copy(vehicles = demo.vehicles.map { it.copy(energyLevel = if (it.name == nearest) 60 else 100) })

    fun vehicleTakingOrder(extensionModules: List<Module>): String {
        val modules = listOf(LoopbackExtension().module()) + extensionModules
        return SimulationKernel(plant, config, modules).use { kernel ->
            kernel.context.runUntil { kernel.core.dispatchContext.vehicles().all { it.currentPosition != null } }
            val order = TransportOrderCreation("T1", listOf(Destination("Storage 01", "Load cargo")))
            kernel.context.execute { kernel.core.createTransportOrder(order) }
            kernel.context.runUntil { kernel.core.orders.get("T1")?.state?.isFinal == true }
            kernel.core.orders.require("T1").state shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("T1").processingVehicle!!
        }
    }

    test("the extension is found through ServiceLoader") {
        Extensions.discover().map { it.name } shouldContain "nearest-vehicle-dispatcher"
    }

    test("kTCS's default dispatcher gives the order to a vehicle with more energy") {
        vehicleTakingOrder(emptyList()) shouldNotBe nearest
    }

    test("the replacement gives it to the nearest vehicle") {
        vehicleTakingOrder(listOf(NearestVehicleDispatcherExtension().module())) shouldBe nearest
    }

    test("the extension's module replaces the kernel's dispatcher") {
        val modules = listOf(LoopbackExtension().module(), NearestVehicleDispatcherExtension().module())
        SimulationKernel(plant, config, modules).use { kernel ->
            kernel.core.dispatcher.shouldBeInstanceOf<NearestVehicleDispatcher>()
        }
    }
})

/** The vehicle with the cheapest route from its start position to [point], as kTCS's router computes it. */
private fun nearestVehicleTo(model: PlantModel, point: String, config: org.ktcs.extension.config.KtcsConfig): String =
    SimulationKernel(model, config, listOf(LoopbackExtension().module())).use { kernel ->
        val context = kernel.core.dispatchContext
        kernel.context.runUntil { context.vehicles().all { it.currentPosition != null } }
        var nearest = ""
        kernel.context.execute {
            nearest = context.vehicles().minBy { vehicle ->
                context.router.costsFrom(vehicle, vehicle.currentPosition!!)(point) ?: Long.MAX_VALUE
            }.name
        }
        kernel.context.runUntil { nearest.isNotEmpty() }
        nearest
    }
