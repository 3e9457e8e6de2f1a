package org.ktcs.kernel.vehicles

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainOnly
import io.kotest.matchers.shouldBe
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.core.StepDriverFactory
import org.ktcs.kernel.simulation.SimulationKernel

/**
 * The directed square A -> B -> C -> D -> A with a detour A -> K -> B and a spur out of each corner (A -> A2, ...).
 * Three vehicles on B, C and D are each sent one corner on and out; they wait for each other and for A. The fourth
 * stands on A and is sent over B: its first step would close the cycle, so it takes the detour, which leaves A free.
 */
class BlockedStartTest : FunSpec({
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }
    val square = listOf("A" to "B", "B" to "C", "C" to "D", "D" to "A", "A" to "K", "K" to "B") +
        listOf("A", "B", "C", "D").map { it to "${it}2" }
    val plant = PlantModel(
        "square with a detour",
        points = listOf("A", "B", "C", "D", "K", "A2", "B2", "C2", "D2").map { Point(it) },
        paths = square.map { (from, to) -> Path("$from --- $to", from, to, length = 2000) },
        vehicles = listOf("A", "B", "C", "D").map {
            Vehicle("V$it", properties = mapOf("loopback:initialPosition" to it))
        },
    )

    test("a vehicle whose first step would close a cycle of waiting vehicles takes the detour that leaves its point") {
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
        )
        SimulationKernel(plant, config, listOf(drivers)).use { kernel ->
            fun send(vehicle: String, to: String) = kernel.context.execute {
                kernel.core.createTransportOrder(
                    TransportOrderCreation(
                        "To-$to",
                        listOf(Destination(to, Operations.MOVE)),
                        intendedVehicle = vehicle,
                    ),
                )
            }
            send("VB", "C2")
            send("VC", "D2")
            send("VD", "A2")
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 500)
            send("VA", "B2")
            val tenMinutes = 600_000L
            kernel.context.runUntil {
                kernel.core.orders.all().all { it.state.isFinal } || kernel.context.elapsedMillis() > tenMinutes
            }

            kernel.core.orders.all().map { it.state }.shouldContainOnly(TransportOrderState.FINISHED)
            kernel.core.watchdog.detected shouldBe 0
        }
    }
})
