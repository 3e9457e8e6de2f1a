package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrderState

class OrderEligibilityTest : FunSpec({
    fun Vehicle.accepting(
        vararg types: String,
    ) = copy(acceptableOrderTypes = types.map { AcceptableOrderType(it, 0) }.toSet())

    context("order types") {
        test("a vehicle takes an order whose type it accepts, and '*' accepts every type") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1").accepting("Transport"), vehicle("V2", at = "H").accepting("*"))
            context.add(order("T1", type = "Transport", intended = "V1"), order("T2", type = "Other", intended = "V2"))

            context.dispatch()

            context.assignedOrder("V1") shouldBe "T1"
            context.assignedOrder("V2") shouldBe "T2"
        }

        test("an order whose type no vehicle accepts waits, saying so") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1").accepting("Park"), vehicle("V2").accepting("Charge"))
            context.add(order("T1", type = "Transport"))

            context.dispatch()

            context.assignments.shouldBeEmpty()
            context.deferralsOf("T1") shouldContainExactly listOf("no vehicle accepts type 'Transport'")
        }

        test("the vehicle's allowed order types must admit the type too") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1").copy(allowedOrderTypes = setOf("Park")), order("T1", type = "Transport"))

            context.dispatch()

            context.deferralsOf("T1") shouldContainExactly listOf("vehicle V1: does not accept type 'Transport'")
        }
    }

    test("an order intended for a vehicle goes to that vehicle only, and says so while it is busy") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1", at = "E"), vehicle("V2", at = "A", energy = 10).processing("X"))
        context.add(order("X", state = TransportOrderState.BEING_PROCESSED), order("T1", intended = "V2"))

        context.dispatch()

        context.assignments.shouldBeEmpty()
        context.deferralsOf("T1") shouldContainExactly listOf("intended vehicle V2: processing order X")
    }

    test("an order to a locked location waits, saying so") {
        val context = FakeDispatchContext(plant(station("S3", "H", locked = true)))
        context.add(vehicle("V1"), order("T1", load("S1"), load("S3")))

        context.dispatch()

        context.assignments.shouldBeEmpty()
        context.deferralsOf("T1") shouldContainExactly listOf("target location S3 is locked")
    }

    test("an order no vehicle can reach waits, saying from where") {
        val context = FakeDispatchContext(plant(station("Island", "Z")))
        context.add(vehicle("V1"), order("T1", load("Island")))

        context.dispatch()

        context.deferralsOf("T1") shouldContainExactly listOf("vehicle V1: no route from A")
    }

    test("a driver's refusal is recorded with its reasons, once until the reasons change") {
        val context = FakeDispatchContext(plant())
        context.add(vehicle("V1"), order("T1"))
        val dispatcher = context.dispatcher()
        var reason = "cannotLoadWhenLoaded"
        context.driver = { _, _ -> Explained.no(reason) }

        dispatcher.dispatch()
        dispatcher.dispatch()
        reason = "batteryDoorOpen"
        dispatcher.dispatch()

        context.assignments.shouldBeEmpty()
        context.deferralsOf("T1") shouldContainExactly listOf(
            "vehicle V1: driver refused: cannotLoadWhenLoaded",
            "vehicle V1: driver refused: batteryDoorOpen",
        )
    }

    test("a vehicle with critical energy only takes an order that starts with its recharge operation") {
        val context = FakeDispatchContext(plant(charger("C1", "B")))
        context.add(
            vehicle("V1", energy = 30),
            order("T1"),
            order("R1", Destination("C1", "CHARGE"), created = T0.plusSeconds(1)),
        )

        // openTCS's ranking, so that the vehicle is asked about the older order first.
        context.dispatch(assignOnly.copy(orderCandidatePriorities = listOf(CandidatePriority.BY_DEADLINE)))

        context.assignedOrder("V1") shouldBe "R1"
        context.deferralsOf("T1") shouldContainExactly listOf("vehicle V1: energy level critical")
    }

    context("redundant orders") {
        val toCurrentPoint = listOf(moveTo("A"), Destination("S1", Operations.NOP))

        test("an order that only moves a vehicle to where it stands, or does nothing there, is not assigned") {
            toCurrentPoint.forEach { destination ->
                val context = FakeDispatchContext(plant())
                context.add(vehicle("V1", at = if (destination.target == "A") "A" else "C"), order("T1", destination))

                context.dispatch()

                context.assignedOrder("V1").shouldBeNull()
                context.deferralsOf("T1").single() shouldBe
                    "vehicle V1: already at ${context.vehicles.getValue(
                        "V1",
                    ).currentPosition}, where the order does nothing"
            }
        }

        test("assignRedundantOrders assigns it anyway") {
            val context = FakeDispatchContext(plant())
            context.add(vehicle("V1"), order("T1", moveTo("A")))

            context.dispatch(assignOnly.copy(assignRedundantOrders = true))

            context.assignedOrder("V1") shouldBe "T1"
        }
    }

    context("orders in sequences") {
        test("only the next order of a sequence without vehicle is free") {
            val context = FakeDispatchContext(plant())
            context.add(OrderSequence("Seq", T0, orders = listOf("First", "Second"), finishedIndex = -1))
            context.add(vehicle("V1"), vehicle("V2"))
            context.add(
                order("Second", sequence = "Seq"),
                order("First", sequence = "Seq", created = T0.plusSeconds(1)),
            )

            context.dispatch()

            context.assignments.map { it.order } shouldContainExactly listOf("First")
        }

        test("an order of a sequence another vehicle processes is not free") {
            val context = FakeDispatchContext(plant())
            context.add(OrderSequence("Seq", T0, orders = listOf("First"), processingVehicle = "V9"))
            context.add(vehicle("V1"), order("First", sequence = "Seq"))

            context.dispatch()

            context.assignments.shouldBeEmpty()
            context.deferrals.shouldBeEmpty()
        }
    }
})
