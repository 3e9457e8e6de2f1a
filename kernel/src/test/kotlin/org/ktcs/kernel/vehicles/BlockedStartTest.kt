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

    // A two-way aisle P (a station stub) - Y - W1 - W2 - T, and a longer one-way way round Y -> E1 -> E2 -> E3 -> T.
    // VB, on W2, is sent to the station at P, where VA stands; then VA is sent to T. VA's first step (out of the stub)
    // has no alternative, but the vehicle it would meet head-on stands two steps further on.
    test("a vehicle whose claim would meet a waiting vehicle head-on on a two-way aisle takes the way round") {
        val aisle = listOf("P" to "Y", "Y" to "W1", "W1" to "W2", "W2" to "T").map { (from, to) ->
            Path("$from --- $to", from, to, length = 2000, maxReverseVelocity = 1000)
        }
        val wayRound = listOf("Y" to "E1", "E1" to "E2", "E2" to "E3", "E3" to "T").map { (from, to) ->
            Path("$from --- $to", from, to, length = 2000)
        }
        val aislePlant = PlantModel(
            "two-way aisle with a way round",
            points = listOf("P", "Y", "W1", "W2", "T", "E1", "E2", "E3").map { Point(it) },
            paths = aisle + wayRound,
            vehicles = listOf("P", "W2").map { Vehicle("V$it", properties = mapOf("loopback:initialPosition" to it)) },
            locationTypes = listOf(LocationType("station", setOf("Load"))),
            locations = listOf(Location("S", "station", links = listOf(Link("P")))),
        )
        SimulationKernel(aislePlant, config, listOf(drivers)).use { kernel ->
            kernel.send("VW2", Destination("S", "Load"))
            kernel.context.runUntilTime(kernel.context.elapsedMillis() + 500)
            kernel.send("VP", Destination("T", Operations.MOVE))
            kernel.context.runUntil {
                kernel.core.orders.all().all { it.state.isFinal } || kernel.context.elapsedMillis() > 600_000L
            }

            kernel.core.orders.all().map { it.state }.shouldContainOnly(TransportOrderState.FINISHED)
            kernel.core.watchdog.detected shouldBe 0
            val route = kernel.core.orders.require("To-T").driveOrders.single().route!!
            route.steps.mapNotNull { it.path } shouldBe listOf("P --- Y") + wayRound.map { it.name }
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
