package org.ktcs.e2e.extensions

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import io.kotest.matchers.types.shouldBeInstanceOf
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.extension.Extensions
import org.ktcs.kernel.simulation.SimulationKernel

/** A driver and a dispatcher from outside the kernel, found through ServiceLoader, replace the defaults. */
class ExtensionsTakeEffectTest : FunSpec({
    test("the teleport driver drives the vehicles and the first-idle-vehicle dispatcher assigns every order") {
        val extensions = Extensions.discover()
        extensions.map { it.name } shouldContainAll listOf("first-idle-vehicle-dispatcher", "loopback")
        val demo = PlantModelLoader.loadDemo().model
        val model = demo.copy(
            vehicles = demo.vehicles.map {
                it.copy(
                    properties = it.properties + ("tcs:preferredAdapterClass" to "teleport"),
                )
            },
        )
        val config = ConfigLoader().load(null, emptyMap(), listOf("dispatcher.parkIdleVehicles=false"))

        SimulationKernel(model, config, extensions.map { it.module() }).use { kernel ->
            kernel.core.plant.vehicles().map {
                kernel.core.controllers.driverName(it.name)
            }.toSet() shouldBe setOf("teleport")
            // One order after the other: this naive dispatcher parks nobody, so idle vehicles would block each other.
            repeat(5) { index ->
                val creation =
                    TransportOrderCreation(
                        "T$index",
                        listOf(Destination("Storage 01", "Load cargo"), Destination("Goods out 01", "Unload cargo")),
                    )
                kernel.context.execute { kernel.core.createTransportOrder(creation) }
                kernel.context.runUntil {
                    kernel.core.orders.get("T$index")?.state?.isFinal == true ||
                        kernel.context.elapsedMillis() > 3_600_000
                }
                kernel.core.orders.require("T$index").state shouldBe TransportOrderState.FINISHED
            }

            kernel.core.dispatcher.shouldBeInstanceOf<FirstIdleVehicleDispatcher>().assignments shouldBe 5
        }
    }
})
