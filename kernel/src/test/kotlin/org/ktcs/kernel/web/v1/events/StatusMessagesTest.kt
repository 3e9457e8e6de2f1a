package org.ktcs.kernel.web.v1.events

import io.kotest.core.spec.style.FunSpec
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Position
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.without
import java.time.Instant

class StatusMessagesTest : FunSpec({
    // kTCS has no peripheral jobs, so the sample's third message (a PeripheralJob) has no kTCS counterpart.
    fun expected(angle: String) =
        GoldenJson.element("binding/GetEventsResponseTOTest.jsonSample.orientationAngle-$angle.approved.txt")
            .without("statusMessages.2")

    fun encoded(angle: Double) = V1Json.json.encodeToString(
        GetEventsResponse.serializer(),
        GetEventsResponse(
            timeStamp = Instant.EPOCH.toString(),
            statusMessages = listOf(
                sampleVehicle(angle).toStatusMessage(0, Instant.EPOCH),
                sampleOrder().toStatusMessage(1, Instant.EPOCH),
            ),
        ),
    )

    test("encodes vehicle and order status messages as openTCS's GET /events sample") {
        encoded(90.0) shouldEqualJsonElement expected("90.0")
    }

    test("writes a vehicle's unknown orientation angle as the string NaN") {
        encoded(Double.NaN) shouldEqualJsonElement expected("NaN")
    }
})

private fun sampleVehicle(angle: Double) = Vehicle(
    name = "some-vehicle",
    properties = mapOf("some-key" to "some-value"),
    transportOrder = "some-transport-order",
    boundingBox = BoundingBox(500, 400, 500, Couple(20, 20)),
    energyLevelThresholdSet = EnergyLevelThresholdSet(
        critical = 20,
        good = 95,
        sufficientlyRecharged = 40,
        fullyRecharged = 80,
    ),
    energyLevel = 70,
    integrationLevel = IntegrationLevel.TO_BE_UTILIZED,
    currentPosition = "some-point",
    precisePosition = Position(1, 2, 3),
    orientationAngle = angle,
    state = VehicleState.IDLE,
    stateTimestamp = Instant.parse("2025-01-29T11:12:43Z"),
    procState = ProcState.IDLE,
    procStateTimestamp = Instant.parse("2025-01-29T11:58:02Z"),
    allocatedResources = listOf(setOf("some-path", "some-point"), setOf("some-other-path", "some-other-point")),
    claimedResources = listOf(setOf("some-path", "some-point"), setOf("some-other-path", "some-other-point")),
    acceptableOrderTypes = setOf(AcceptableOrderType("some-order-type", 1)),
    envelopeKey = "some-envelope-key",
)

private fun sampleOrder() = TransportOrder(
    name = "some-order",
    driveOrders = listOf(
        DriveOrder(
            name = "drive-order-1",
            destination = Destination(
                "some-location",
                "some-operation",
                linkedMapOf("some-key" to "some-value", "some-other-key" to "some-other-value"),
            ),
            state = DriveOrderState.TRAVELLING,
        ),
    ),
    type = "some-order-type",
    state = TransportOrderState.BEING_PROCESSED,
    creationTime = Instant.EPOCH,
    intendedVehicle = "some-intended-vehicle",
    processingVehicle = "some-vehicle",
    wrappingSequence = "some-wrapping-sequence",
    dispensable = true,
    peripheralReservationToken = "some-peripheral-reservation-token",
    properties = linkedMapOf("some-key" to "some-value", "some-other-key" to "some-other-value"),
)
