package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrderState

class SequenceSuccessorsTest : FunSpec({
    fun sequenceContext(vararg states: TransportOrderState, finishedIndex: Int = 0): FakeDispatchContext {
        val names = states.indices.map { "Seq-$it" }
        return FakeDispatchContext(plant()).apply {
            add(OrderSequence("Seq", T0, orders = names, finishedIndex = finishedIndex, processingVehicle = "V1"))
            states.forEachIndexed { index, state -> add(order(names[index], sequence = "Seq", state = state)) }
            add(vehicle("V1", energy = 20).copy(orderSequence = "Seq"))
        }
    }

    test("an idle vehicle bound to a sequence gets its next order, even with critical energy") {
        val context = sequenceContext(TransportOrderState.FINISHED, TransportOrderState.DISPATCHABLE)

        context.dispatch()

        context.assignedOrder("V1") shouldBe "Seq-1"
    }

    // The successor check once skipped the charging rule that holds every other vehicle until it has recharged.
    test("a vehicle bound to a sequence that charges gets its next order only when recharged, like any other") {
        val context = sequenceContext(TransportOrderState.FINISHED, TransportOrderState.DISPATCHABLE)
        context.vehicles["V1"] = context.vehicles.getValue("V1").copy(state = VehicleState.CHARGING)

        context.dispatch()
        context.assignments.shouldBeEmpty()

        context.vehicles["V1"] = context.vehicles.getValue("V1").copy(energyLevel = 95)
        context.dispatch()
        context.assignedOrder("V1") shouldBe "Seq-1"
    }

    test("the next order is not skipped while it is not dispatchable yet") {
        val context =
            sequenceContext(TransportOrderState.FINISHED, TransportOrderState.ACTIVE, TransportOrderState.DISPATCHABLE)

        context.dispatch()

        context.assignments.shouldBeEmpty()
    }

    test("the sequence's orders go to no other vehicle") {
        val context = sequenceContext(TransportOrderState.FINISHED, TransportOrderState.DISPATCHABLE)
        context.vehicles["V1"] = context.vehicles.getValue("V1").copy(paused = true)
        context.add(vehicle("V2"))

        context.dispatch()

        context.assignments.shouldBeEmpty()
    }

    test("a vehicle on a dispensable order of its sequence gets the next order at once") {
        val context = sequenceContext(TransportOrderState.FINISHED, TransportOrderState.DISPATCHABLE)
        context.add(
            order(
                "Wait",
                moveTo("D"),
                sequence = "Seq",
                dispensable = true,
                state = TransportOrderState.BEING_PROCESSED,
            ),
        )
        context.sequences["Seq"] =
            context.sequences.getValue("Seq").let { it.copy(orders = listOf("Seq-0", "Wait", "Seq-1")) }
        context.vehicles["V1"] = context.vehicles.getValue("V1").processing("Wait")

        context.dispatch()

        context.assignedOrder("V1") shouldBe "Seq-1"
        context.withdrawn shouldContainExactly listOf("Wait")
    }

    test("a successor the vehicle cannot take is deferred with the reason") {
        val context = sequenceContext(TransportOrderState.FINISHED, TransportOrderState.DISPATCHABLE)
        context.vehicles["V1"] =
            context.vehicles.getValue("V1").copy(acceptableOrderTypes = setOf(AcceptableOrderType("Park", 0)))

        context.dispatch()

        context.assignments.shouldBeEmpty()
        context.deferralsOf("Seq-1") shouldContainExactly listOf("vehicle V1: does not accept type '-'")
    }
})
