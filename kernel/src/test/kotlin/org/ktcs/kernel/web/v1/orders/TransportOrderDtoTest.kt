package org.ktcs.kernel.web.v1.orders

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.order.VehicleOrientation
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.with
import java.time.Instant

class TransportOrderDtoTest : FunSpec({
    test("encodes a transport order as openTCS's GET sample, apart from what kTCS derives or lacks") {
        val expected = GoldenJson.element("binding/GetTransportOrderResponseTOTest.jsonSample.approved.txt")
            // kTCS derives a drive order's transport order from the order holding it, and the destination states
            // from the drive orders; openTCS's sample fills both with unrelated values.
            .with("driveOrders.0.transportOrder", "some-order")
            .with("destinations.0", Json.parseToJsonElement(DERIVED_DESTINATION.trimMargin()))
            // kTCS keeps no per-step costs and does not reroute.
            .with("driveOrders.0.route.steps.0.costs", 0)
            .with("driveOrders.0.route.steps.0.reroutingType", null as String?)

        V1Json.json.encodeToString(TransportOrderDto.serializer(), sampleOrder().toDto()) shouldEqualJsonElement
            expected
    }

    test("writes an unfinished order's finished time and a missing route as openTCS does") {
        val order = sampleOrder().copy(finishedTime = null, driveOrders = listOf(sampleDriveOrder().copy(route = null)))

        val json = Json.parseToJsonElement(V1Json.json.encodeToString(TransportOrderDto.serializer(), order.toDto()))

        json.jsonObject["finishedTime"]?.jsonPrimitive?.content shouldBe "+1000000000-12-31T23:59:59.999999999Z"
        json.jsonObject.getValue("driveOrders").jsonArray[0].jsonObject["route"] shouldBe JsonNull
    }
})

private const val DERIVED_DESTINATION = """{"locationName":"location-1","operation":"operation-1","state":"OPERATING",
    |"properties":[{"key":"key","value":"value"}]}"""

private fun sampleDriveOrder() = DriveOrder(
    name = "DriveOrder-1",
    destination = Destination("location-1", "operation-1", mapOf("key" to "value")),
    route = Route(listOf(Step("path1", "point1", "point2", VehicleOrientation.FORWARD, routeIndex = 1)), costs = 1000),
    state = DriveOrderState.OPERATING,
)

private fun sampleOrder() = TransportOrder(
    name = "some-order",
    driveOrders = listOf(sampleDriveOrder()),
    type = "some-type",
    state = TransportOrderState.BEING_PROCESSED,
    creationTime = Instant.EPOCH,
    deadline = Instant.EPOCH,
    finishedTime = Instant.EPOCH,
    intendedVehicle = "some-vehicle",
    processingVehicle = "some-vehicle",
    dependencies = setOf("order-1"),
    wrappingSequence = "some-sequence",
    dispensable = true,
    peripheralReservationToken = "some-token",
    currentDriveOrderIndex = 1,
    currentRouteStepIndex = 1,
    properties = linkedMapOf("some-key" to "some-value", "another-key" to "another-value"),
    history = listOf(HistoryEntry(Instant.EPOCH, "code-1", "supp-1")),
)
