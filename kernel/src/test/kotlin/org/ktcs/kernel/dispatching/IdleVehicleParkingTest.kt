package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrderState

class IdleVehicleParkingTest : FunSpec({
    val parking = DispatcherConfiguration(rechargeIdleVehicles = false)
    val prioritized = parking.copy(considerParkingPositionPriorities = true)
    val reparking = prioritized.copy(reparkVehiclesToHigherPriorityPositions = true)

    fun FakeDispatchContext.parkTargets() = created.map {
        it.intendedVehicle to
            it.driveOrders.single().destination.target
    }

    fun parkContext(park: Set<String>, priorities: Map<String, Int> = emptyMap()) =
        FakeDispatchContext(plant(park = park, priorities = priorities))

    test("an idle vehicle off a park position is sent to the closest free one, in the same run") {
        val context = parkContext(setOf("A", "H")).apply { add(vehicle("V1", at = "F")) }

        context.dispatch(parking)

        val order = context.created.single()
        order.name shouldBe "Park-01"
        order.type shouldBe PARK_ORDER_TYPE
        order.intendedVehicle shouldBe "V1"
        order.dispensable shouldBe true
        order.driveOrders.single().destination shouldBe Destination("H", Operations.PARK)
        context.assignedOrder("V1") shouldBe "Park-01"
    }

    test("a vehicle on a park position, one refusing Park orders, and any vehicle with parking off stay put") {
        parkContext(setOf("H")).apply { add(vehicle("V1", at = "H")) }.run {
            dispatch(parking)
            created.shouldBeEmpty()
        }
        parkContext(setOf("H")).apply {
            add(vehicle("V1").copy(acceptableOrderTypes = setOf(AcceptableOrderType("X", 0))))
        }.run {
            dispatch(parking)
            created.shouldBeEmpty()
        }
        parkContext(setOf("H")).apply { add(vehicle("V1")) }.run {
            dispatch(assignOnly)
            created.shouldBeEmpty()
        }
    }

    test("park positions that are occupied or that another order ends at are skipped") {
        val occupied = parkContext(setOf("A", "H")).apply { add(vehicle("V1", at = "F"), vehicle("V2", at = "H")) }
        val targeted = parkContext(setOf("A", "H")).apply {
            add(vehicle("V1", at = "F"), vehicle("V2", at = "B").processing("X"))
            add(order("X", moveTo("H"), state = TransportOrderState.BEING_PROCESSED))
        }

        listOf(occupied, targeted).forEach { context ->
            context.dispatch(parking)
            context.parkTargets() shouldContainExactly listOf("V1" to "A")
        }
    }

    test("no run sends two vehicles to the same park position, and no second run parks a vehicle again") {
        val one = parkContext(setOf("H")).apply { add(vehicle("V1", at = "F"), vehicle("V2", at = "G")) }
        val two = parkContext(setOf("A", "H")).apply { add(vehicle("V1", at = "F"), vehicle("V2", at = "G")) }

        one.dispatcher(parking).apply {
            dispatch()
            dispatch()
        }
        two.dispatch(parking)

        one.parkTargets() shouldContainExactly listOf("V1" to "H")
        two.parkTargets() shouldContainExactly listOf("V1" to "H", "V2" to "A")
    }

    test("a vehicle must have been idle for the park delay") {
        val context = parkContext(setOf("H")).apply { add(vehicle("V1")) }
        val dispatcher = context.dispatcher(parking.copy(parkIdleVehiclesDelayMillis = 30_000))

        dispatcher.dispatch()
        context.created.shouldBeEmpty()

        context.clock.advance(30_000)
        dispatcher.dispatch()
        context.parkTargets() shouldContainExactly listOf("V1" to "H")
    }

    test("with priorities considered the best priority wins over distance, and points without one come last") {
        val byPriority = { configuration: DispatcherConfiguration, priorities: Map<String, Int>, at: String ->
            parkContext(setOf("B", "H"), priorities).apply { add(vehicle("V1", at = at)) }.run {
                dispatch(configuration)
                parkTargets().single().second
            }
        }

        byPriority(parking, mapOf("B" to 1, "H" to 5), "G") shouldBe "H"
        byPriority(prioritized, mapOf("B" to 1, "H" to 5), "G") shouldBe "B"
        byPriority(prioritized, mapOf("H" to 5), "C") shouldBe "H"
    }

    test("an assigned parking position is the only choice, a preferred one comes first while free") {
        fun target(property: String, occupyH: Boolean) = parkContext(setOf("A", "H")).apply {
            add(vehicle("V1", at = "B", properties = mapOf(property to "H")))
            if (occupyH) add(vehicle("V2", at = "H"))
        }.run {
            dispatch(prioritized)
            parkTargets().map { it.second }
        }

        target(DispatcherProperties.ASSIGNED_PARKING_POSITION, occupyH = false) shouldContainExactly listOf("H")
        target(DispatcherProperties.ASSIGNED_PARKING_POSITION, occupyH = true).shouldBeEmpty()
        target(DispatcherProperties.PREFERRED_PARKING_POSITION, occupyH = false) shouldContainExactly listOf("H")
        target(DispatcherProperties.PREFERRED_PARKING_POSITION, occupyH = true) shouldContainExactly listOf("A")
    }

    context("reparking") {
        val priorities = mapOf("A" to 1, "D" to 2, "H" to 3)

        test("a parked vehicle moves on to a free park position of higher priority") {
            val context = parkContext(setOf("A", "H"), priorities).apply { add(vehicle("V1", at = "H")) }

            context.dispatch(reparking)

            context.parkTargets() shouldContainExactly listOf("V1" to "A")
        }

        test("without reparking, or on the best position, a parked vehicle stays") {
            parkContext(setOf("A", "H"), priorities).apply { add(vehicle("V1", at = "H")) }.run {
                dispatch(prioritized)
                created.shouldBeEmpty()
            }
            parkContext(setOf("A", "H"), priorities).apply { add(vehicle("V1", at = "A")) }.run {
                dispatch(reparking)
                created.shouldBeEmpty()
            }
        }

        test("the vehicle on the worst position moves first") {
            val context = parkContext(setOf("A", "D", "H"), priorities)
            context.add(vehicle("V1", at = "D"), vehicle("V2", at = "H"))

            context.dispatch(reparking)

            context.parkTargets() shouldContainExactly listOf("V2" to "A")
        }
    }

    test("a vehicle with a dispensable order waiting for it gets no second one") {
        val context = parkContext(setOf("H")).apply { add(vehicle("V1")) }
        context.add(order("Park-Old", moveTo("Nowhere"), intended = "V1", dispensable = true))

        context.dispatch(parking)

        context.created.shouldBeEmpty()
    }
})
