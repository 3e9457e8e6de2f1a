package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldNotContain
import io.kotest.matchers.shouldBe
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.simulation.SimulationKernel

/** Withdrawals, dependencies, sequences and locks, through the kernel on virtual time with test vehicles. */
class KernelOperationsTest : FunSpec({
    val config = ConfigLoader().load(
        null,
        emptyMap(),
        listOf("dispatcher.parkIdleVehicles=false", "dispatcher.rechargeIdleVehicles=false"),
    )
    val drivers = module { single { StepDriverFactory() } bind VehicleDriverFactory::class }

    fun kernel() = SimulationKernel(PlantModelLoader.loadDemo().model, config, listOf(drivers))

    fun SimulationKernel.run(action: KernelCore.() -> Unit) {
        var done = false
        context.execute {
            core.action()
            done = true
        }
        context.runUntil { done }
    }

    fun SimulationKernel.runFor(millis: Long) = context.runUntilTime(context.elapsedMillis() + millis)

    fun SimulationKernel.state(order: String) = core.orders.require(order).state

    val longTrip = listOf(Destination("Goods in north 01", "Load cargo"), Destination("Goods out 02", "Unload cargo"))

    test("an order waits for its dependency to finish before it is dispatched") {
        kernel().use { kernel ->
            kernel.run {
                createTransportOrder(TransportOrderCreation("First", longTrip, intendedVehicle = "Vehicle-01"))
                createTransportOrder(TransportOrderCreation("Second", longTrip, dependencies = setOf("First")))
            }
            kernel.state("Second") shouldBe TransportOrderState.ACTIVE
            kernel.context.runUntil { kernel.state("First") == TransportOrderState.FINISHED }
            kernel.state("Second") shouldBe TransportOrderState.DISPATCHABLE
            kernel.context.runUntil { kernel.state("Second").isFinal }
            kernel.state("Second") shouldBe TransportOrderState.FINISHED
        }
    }

    test("immediate withdrawal fails the order at once and frees everything but the vehicle's position") {
        kernel().use { kernel ->
            kernel.run { createTransportOrder(TransportOrderCreation("T", longTrip, intendedVehicle = "Vehicle-02")) }
            kernel.runFor(3_000)
            kernel.state("T") shouldBe TransportOrderState.BEING_PROCESSED
            kernel.run { withdraw("T", immediate = true, disableVehicle = false) }

            kernel.state("T") shouldBe TransportOrderState.FAILED
            val vehicle = kernel.core.plant.vehicle("Vehicle-02")
            vehicle.transportOrder shouldBe null
            vehicle.allocatedResources shouldBe listOf(setOf(vehicle.currentPosition!!))
            kernel.core.scheduler.allocations()["Vehicle-02"] shouldBe setOf(vehicle.currentPosition!!)
        }
    }

    test("regular withdrawal lets the vehicle finish what it was sent, then fails the order") {
        kernel().use { kernel ->
            kernel.run { createTransportOrder(TransportOrderCreation("T", longTrip, intendedVehicle = "Vehicle-03")) }
            kernel.runFor(3_000)
            val granted = kernel.core.scheduler.allocations().getValue("Vehicle-03")
            kernel.run { withdraw("T", immediate = false, disableVehicle = true) }
            kernel.state("T") shouldBe TransportOrderState.WITHDRAWN
            // Taking the vehicle out of dispatching must not take away what it is still driving on.
            kernel.core.scheduler.allocations().getValue("Vehicle-03") shouldBe granted
            kernel.context.runUntil { kernel.state("T").isFinal }
            kernel.state("T") shouldBe TransportOrderState.FAILED
            kernel.core.plant.vehicle("Vehicle-03").integrationLevel.name shouldBe "TO_BE_RESPECTED"
        }
    }

    test("an unassigned order is withdrawn straight to FAILED") {
        kernel().use { kernel ->
            kernel.run {
                createTransportOrder(TransportOrderCreation("Blocker", longTrip, intendedVehicle = "Vehicle-01"))
                createTransportOrder(TransportOrderCreation("T", longTrip, dependencies = setOf("Blocker")))
                withdraw("T", immediate = false, disableVehicle = false)
            }
            kernel.state("T") shouldBe TransportOrderState.FAILED
        }
    }

    test("a failure-fatal sequence fails the orders after a failed one and finishes when complete") {
        kernel().use { kernel ->
            kernel.run {
                createOrderSequence(OrderSequenceCreation("Seq", failureFatal = true, intendedVehicle = "Vehicle-04"))
                createTransportOrder(
                    TransportOrderCreation("S1", longTrip, intendedVehicle = "Vehicle-04", wrappingSequence = "Seq"),
                )
                createTransportOrder(
                    TransportOrderCreation("S2", longTrip, intendedVehicle = "Vehicle-04", wrappingSequence = "Seq"),
                )
                markSequenceComplete("Seq")
            }
            kernel.runFor(3_000)
            kernel.run { withdraw("S1", immediate = true, disableVehicle = false) }

            kernel.state("S2") shouldBe TransportOrderState.FAILED
            val sequence = kernel.core.sequences.require("Seq")
            sequence.orders shouldBe listOf("S1", "S2")
            sequence.finished shouldBe true
        }
    }

    test("a sequence marked complete after its last order finished finishes then and is swept in time") {
        val sweeping = ConfigLoader().load(
            null,
            emptyMap(),
            listOf(
                "dispatcher.parkIdleVehicles=false",
                "dispatcher.rechargeIdleVehicles=false",
                "orderpool.sweepInterval=1000",
                "orderpool.sweepAge=5000",
            ),
        )
        SimulationKernel(PlantModelLoader.loadDemo().model, sweeping, listOf(drivers)).use { kernel ->
            kernel.run {
                createOrderSequence(OrderSequenceCreation("Seq"))
                createTransportOrder(TransportOrderCreation("S1", longTrip, wrappingSequence = "Seq"))
            }
            kernel.context.runUntil { kernel.state("S1").isFinal }
            kernel.run { markSequenceComplete("Seq") }
            val completedAt = kernel.context.now()

            val sequence = kernel.core.sequences.require("Seq")
            sequence.finished shouldBe true
            sequence.finishedTime shouldBe completedAt
            kernel.runFor(7_000)
            kernel.core.sequences.get("Seq") shouldBe null
        }
    }

    test("orders of a sequence are processed in order by one vehicle") {
        kernel().use { kernel ->
            kernel.run {
                createOrderSequence(OrderSequenceCreation("Seq"))
                createTransportOrder(TransportOrderCreation("S1", longTrip, wrappingSequence = "Seq"))
                createTransportOrder(TransportOrderCreation("S2", longTrip, wrappingSequence = "Seq"))
                markSequenceComplete("Seq")
            }
            kernel.context.runUntil { kernel.core.sequences.require("Seq").finished }
            val s1 = kernel.core.orders.require("S1")
            val s2 = kernel.core.orders.require("S2")
            s1.state shouldBe TransportOrderState.FINISHED
            s2.processingVehicle shouldBe s1.processingVehicle
            (s2.finishedTime!! > s1.finishedTime!!) shouldBe true
        }
    }

    test("a locked path is left out of the routes of new orders") {
        kernel().use { kernel ->
            val path = "Point-0001 --- Point-0002"
            kernel.run {
                setPathLocked(path, true)
                createTransportOrder(TransportOrderCreation("T", longTrip))
            }
            kernel.context.runUntil { kernel.state("T").isFinal }
            kernel.state("T") shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("T").driveOrders.flatMap { it.route!!.steps }.none { it.path == path } shouldBe
                true
        }
    }

    test("locking a path on a vehicle's way routes it around the path") {
        // A long approach A -> W -> X (the vehicle is sent two steps ahead), then a short way X -> B -> D and a
        // longer one X -> C -> D.
        val diamond = PlantModel(
            "diamond",
            points = listOf("A", "W", "X", "B", "C", "D").map { Point(it) },
            paths = listOf(
                Path("A --- W", "A", "W", 10_000),
                Path("W --- X", "W", "X", 10_000),
                Path("X --- B", "X", "B", 1_000),
                Path("B --- D", "B", "D", 1_000),
                Path("X --- C", "X", "C", 5_000),
                Path("C --- D", "C", "D", 5_000),
            ),
            vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
        )
        SimulationKernel(diamond, config, listOf(drivers)).use { kernel ->
            kernel.run { createTransportOrder(TransportOrderCreation("T", listOf(Destination("D", "MOVE")))) }
            kernel.runFor(1_000)
            kernel.core.plant.vehicle("V").claimedResources.flatten() shouldContain "X --- B"
            kernel.run { setPathLocked("X --- B", true) }

            kernel.core.plant.vehicle("V").claimedResources.flatten() shouldNotContain "X --- B"
            kernel.context.runUntil { kernel.state("T").isFinal }
            kernel.state("T") shouldBe TransportOrderState.FINISHED
            kernel.core.orders.require("T").driveOrders.single().route!!.steps.map { it.path } shouldBe
                listOf("A --- W", "W --- X", "X --- C", "C --- D")
        }
    }

    test("an order whose destinations no path connects is UNROUTABLE at once") {
        val islands = PlantModel(
            "islands",
            points = listOf(Point("A"), Point("B"), Point("C")),
            paths = listOf(Path("A --- B", "A", "B", 1000, maxReverseVelocity = 1000)),
            vehicles = listOf(Vehicle("V", properties = mapOf("loopback:initialPosition" to "A"))),
        )
        SimulationKernel(islands, config, listOf(drivers)).use { kernel ->
            kernel.run {
                createTransportOrder(
                    TransportOrderCreation("Cut off", listOf(Destination("B", "MOVE"), Destination("C", "MOVE"))),
                )
            }
            kernel.state("Cut off") shouldBe TransportOrderState.UNROUTABLE
        }
    }

    test("a paused vehicle gets no further resources until it is resumed") {
        kernel().use { kernel ->
            kernel.run { createTransportOrder(TransportOrderCreation("T", longTrip, intendedVehicle = "Vehicle-02")) }
            kernel.runFor(1_000)
            kernel.run { requests.setPaused("Vehicle-02", true) }
            kernel.runFor(600_000)
            kernel.state("T") shouldBe TransportOrderState.BEING_PROCESSED
            kernel.core.plant.vehicle("Vehicle-02").paused shouldBe true
            kernel.run { requests.setPaused("Vehicle-02", false) }
            kernel.context.runUntil { kernel.state("T").isFinal }
            kernel.state("T") shouldBe TransportOrderState.FINISHED
        }
    }
})
