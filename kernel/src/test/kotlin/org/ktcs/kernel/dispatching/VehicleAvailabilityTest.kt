package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrderState

class VehicleAvailabilityTest : FunSpec({
    fun assignedWith(
        vehicle: Vehicle,
        configuration: DispatcherConfiguration = assignOnly,
        setUp: FakeDispatchContext.() -> Unit = {},
    ) =
        FakeDispatchContext(plant()).run {
            add(vehicle)
            add(order("T1"))
            setUp()
            dispatch(configuration)
            assignedOrder(vehicle.name)
        }

    test("an idle, utilized vehicle with a known position gets an order") {
        assignedWith(vehicle("V1")) shouldBe "T1"
    }

    test("a vehicle that is not utilized gets no order") {
        IntegrationLevel.entries.filter { it != IntegrationLevel.TO_BE_UTILIZED }.forEach { level ->
            assignedWith(vehicle("V1").copy(integrationLevel = level)).shouldBeNull()
        }
    }

    test("a vehicle whose position is unknown gets no order") {
        assignedWith(vehicle("V1", at = null)).shouldBeNull()
    }

    test("a paused vehicle gets no order") {
        assignedWith(vehicle("V1").copy(paused = true)).shouldBeNull()
    }

    test("an idle vehicle must report state IDLE or CHARGING") {
        assignedWith(vehicle("V1", state = VehicleState.EXECUTING)).shouldBeNull()
        assignedWith(vehicle("V1", state = VehicleState.ERROR)).shouldBeNull()
        assignedWith(vehicle("V1", state = VehicleState.UNKNOWN)).shouldBeNull()
        assignedWith(vehicle("V1").copy(procState = ProcState.AWAITING_ORDER)).shouldBeNull()
    }

    test("a vehicle busy with an order that is not dispensable gets no other") {
        assignedWith(vehicle("V1").processing("Busy")) {
            add(order("Busy", state = TransportOrderState.BEING_PROCESSED))
        }
            .shouldBeNull()
    }

    test("a charging vehicle is available only when fully recharged, by default") {
        assignedWith(vehicle("V1", energy = 89, state = VehicleState.CHARGING)).shouldBeNull()
        assignedWith(vehicle("V1", energy = 90, state = VehicleState.CHARGING)) shouldBe "T1"
    }

    test("without keepRechargingUntilFullyCharged a charging vehicle is available once recovered") {
        val configuration = assignOnly.copy(keepRechargingUntilFullyCharged = false)
        assignedWith(vehicle("V1", energy = 69, state = VehicleState.CHARGING), configuration).shouldBeNull()
        assignedWith(vehicle("V1", energy = 70, state = VehicleState.CHARGING), configuration) shouldBe "T1"
    }

    test("a vehicle bound to an unfinished order sequence takes no free order") {
        val bound = vehicle("V1").copy(orderSequence = "Seq")
        assignedWith(bound) { add(OrderSequence("Seq", T0, processingVehicle = "V1")) }.shouldBeNull()
        assignedWith(bound) { add(OrderSequence("Seq", T0, processingVehicle = "V1", finished = true)) } shouldBe "T1"
    }

    test("a vehicle on the dispensable last order of a complete sequence takes a free order") {
        val onLast = vehicle("V1").processing("Park").copy(orderSequence = "Seq")
        assignedWith(onLast) {
            add(order("Park", dispensable = true, sequence = "Seq", state = TransportOrderState.BEING_PROCESSED))
            add(OrderSequence("Seq", T0, orders = listOf("Park"), complete = true, processingVehicle = "V1"))
        } shouldBe "T1"
    }

    test("every filter that objects gives its reason, and an available vehicle has none") {
        val context = FakeDispatchContext(plant())
        val availability = VehicleAvailability.of(DispatchRun(context, assignOnly, DefaultRecoveryEvaluator()))
        val unready = vehicle("V1", at = null).copy(paused = true, integrationLevel = IntegrationLevel.TO_BE_RESPECTED)

        availability.reasons(unready) shouldContainExactly
            listOf("integration level TO_BE_RESPECTED", "position unknown", "paused")
        availability.reasons(vehicle("V2")).shouldBeEmpty()
    }
    context("what the vehicle is asked to take") {
        val park = order("Park", dispensable = true, state = TransportOrderState.BEING_PROCESSED)
        val sequence = OrderSequence("Seq", T0, orders = listOf("S1", "S2"), processingVehicle = "V1")
        val availability = VehicleAvailability(mapOf("Park" to park)::get, mapOf("Seq" to sequence)::get)

        test("a vehicle takes only order types it accepts") {
            val picky = vehicle("V1").copy(acceptableOrderTypes = setOf(AcceptableOrderType("Transport", 0)))
            val work = VehicleAvailability.Work(orderType = "Park")

            availability.reasons(picky, work) shouldContainExactly listOf("does not accept type 'Park'")
            availability.isAvailable(picky, VehicleAvailability.Work(orderType = "Transport")) shouldBe true
        }

        test("a vehicle bound to a sequence takes that sequence's orders only") {
            val bound = vehicle("V1").copy(orderSequence = "Seq")

            availability.isAvailable(bound, VehicleAvailability.Work(sequence = "Seq")) shouldBe true
            availability.reasons(bound) shouldContainExactly listOf("bound to order sequence Seq")
        }

        test("a dispensable order is replaced only where the work may replace it") {
            val parking = vehicle("V1").processing("Park")

            availability.isAvailable(parking) shouldBe true
            availability.reasons(parking, VehicleAvailability.Work(mayReplaceDispensable = false)) shouldContainExactly
                listOf("processing order Park")
        }
    }
})
