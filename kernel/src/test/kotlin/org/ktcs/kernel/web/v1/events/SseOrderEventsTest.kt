package org.ktcs.kernel.web.v1.events

import io.kotest.core.spec.style.FunSpec
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.inBothStates
import org.ktcs.kernel.web.v1.with
import java.time.Instant

class SseOrderEventsTest : FunSpec({
    test("encodes a transport order change as openTCS's SSE sample, apart from what kTCS lacks") {
        val event =
            TransportOrderEvent(
                previous = sampleOrder(TransportOrderState.BEING_PROCESSED),
                current = sampleOrder(TransportOrderState.RAW),
            )
        val expected = GoldenJson.element("binding/sse/TransportOrderEventTOTest.jsonSample.approved.txt")
            .inBothStates { withOneSupplement(it).withoutStepCostsAndRerouting(it) }

        V1Json.json.encodeToString(
            ObjectEventDto.serializer(SseTransportOrderDto.serializer()),
            event.toDto(),
        ) shouldEqualJsonElement
            expected
    }

    test("encodes an order sequence change as openTCS's SSE sample, apart from the single history supplement") {
        val event =
            OrderSequenceEvent(previous = sampleSequence(finished = false), current = sampleSequence(finished = true))
        val expected = GoldenJson.element("binding/sse/OrderSequenceEventTOTest.jsonSample.approved.txt")
            .inBothStates { withOneSupplement(it) }

        V1Json.json.encodeToString(
            ObjectEventDto.serializer(SseOrderSequenceDto.serializer()),
            event.toDto(),
        ) shouldEqualJsonElement
            expected
    }
})

// kTCS keeps one supplement per history entry.
private fun JsonElement.withOneSupplement(state: String) =
    with("$state.history.entries.0.supplements", JsonArray(listOf(JsonPrimitive("supplement-1"))))

// kTCS keeps no per-step costs and does not reroute.
private fun JsonElement.withoutStepCostsAndRerouting(state: String) =
    with("$state.driveOrders.0.route.steps.0.costs", 0)
        .with("$state.driveOrders.0.route.steps.0.reroutingType", null as String?)

private val AT_12_03 = Instant.parse("2025-07-22T12:03:00Z")
private val AT_13_03 = Instant.parse("2025-07-22T13:03:00Z")

private fun sampleOrder(state: TransportOrderState) = TransportOrder(
    name = "order-1",
    properties = linkedMapOf("key-1" to "value-1", "key-2" to "value-2"),
    history = listOf(HistoryEntry(AT_12_03, "event-code-1", "supplement-1")),
    type = "type-1",
    dependencies = setOf("dependency-1", "dependency-2"),
    driveOrders = listOf(
        DriveOrder(
            name = "drive-order-1",
            destination = Destination(
                "destination-1",
                "operation-1",
                linkedMapOf(
                    "key-3" to "value-3",
                    "key-4" to "value-4",
                ),
            ),
            route = Route(listOf(Step("path-1", "point-1", "point-2", routeIndex = 1)), costs = 200),
            state = DriveOrderState.TRAVELLING,
        ),
    ),
    peripheralReservationToken = "reservation-token-1",
    currentDriveOrderIndex = 3,
    currentRouteStepIndex = 5,
    state = state,
    creationTime = AT_12_03,
    deadline = AT_13_03,
    finishedTime = Instant.parse("2025-07-22T12:33:00Z"),
    intendedVehicle = "vehicle-1",
    processingVehicle = "vehicle-2",
    wrappingSequence = "sequence-1",
    dispensable = true,
)

private fun sampleSequence(finished: Boolean) = OrderSequence(
    name = "order-sequence-1",
    properties = linkedMapOf("key-1" to "value-1", "key-2" to "value-2"),
    history = listOf(HistoryEntry(AT_12_03, "event-code-1", "supplement-1")),
    type = "type-1",
    orderTypes = setOf("type-1"),
    orders = listOf("order-1", "order-2"),
    finishedIndex = 4,
    complete = true,
    finished = finished,
    failureFatal = true,
    intendedVehicle = "vehicle-1",
    processingVehicle = "vehicle-2",
    creationTime = AT_12_03,
    finishedTime = AT_13_03,
)
