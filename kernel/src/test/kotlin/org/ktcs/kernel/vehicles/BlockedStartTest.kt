package org.ktcs.kernel.vehicles

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainOnly
import io.kotest.matchers.shouldBe
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location
import org.ktcs.api.model.LocationType
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
 * The same holds when its order starts with an operation at station S beside A, where it stands.
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
        locationTypes = listOf(LocationType("station", setOf("Load"))),
        locations = listOf(Location("S", "station", links = listOf(Link("A")))),
    )
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
    )

    fun SimulationKernel.send(vehicle: String, vararg destinations: Destination) = context.execute {
        core.createTransportOrder(
            TransportOrderCreation(
                "To-${destinations.last().target}",
                destinations.toList(),
                intendedVehicle = vehicle,
            ),
        )
    }

    // Three vehicles wait for each other and for A, then VA gets its order; every order must finish undisturbed.
    fun SimulationKernel.startsWithoutDeadlock(vararg orderOfVA: Destination) {
        send("VB", Destination("C2", Operations.MOVE))
        send("VC", Destination("D2", Operations.MOVE))
        send("VD", Destination("A2", Operations.MOVE))
        context.runUntilTime(context.elapsedMillis() + 500)
        send("VA", *orderOfVA)
        val tenMinutes = 600_000L
        context.runUntil { core.orders.all().all { it.state.isFinal } || context.elapsedMillis() > tenMinutes }

        core.orders.all().map { it.state }.shouldContainOnly(TransportOrderState.FINISHED)
        core.watchdog.detected shouldBe 0
    }

    test("a vehicle whose first step would close a cycle of waiting vehicles takes the detour that leaves its point") {
        SimulationKernel(plant, config, listOf(drivers)).use { kernel ->
            kernel.startsWithoutDeadlock(Destination("B2", Operations.MOVE))
        }
    }

    test("an order that starts with an operation where the vehicle stands takes the detour after the operation") {
        SimulationKernel(plant, config, listOf(drivers)).use { kernel ->
            kernel.startsWithoutDeadlock(Destination("S", "Load"), Destination("B2", Operations.MOVE))

            val route = kernel.core.orders.require("To-B2").driveOrders[1].route!!
            route.steps.mapNotNull { it.path } shouldBe listOf("A --- K", "K --- B", "B --- B2")
        }
    }
})
