package org.ktcs.kernel.web.v1.vehicles

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
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.with
import java.time.Instant

class VehicleDtoTest : FunSpec({
    test("encodes a vehicle exactly as openTCS's GET sample") {
        V1Json.json.encodeToString(VehicleDto.serializer(), sampleVehicle(90.0).toDto()) shouldEqualJsonElement
            GoldenJson.element("binding/GetVehicleResponseTOTest.jsonSample.orientationAngle-90.0.approved.txt")
    }

    test("writes an unknown orientation angle as the string NaN") {
        V1Json.json.encodeToString(VehicleDto.serializer(), sampleVehicle(Double.NaN).toDto()) shouldEqualJsonElement
            GoldenJson.element("binding/GetVehicleResponseTOTest.jsonSample.orientationAngle-NaN.approved.txt")
    }

    test("writes null for a vehicle without order, position or envelope key") {
        val vehicle = sampleVehicle(90.0).copy(transportOrder = null, currentPosition = null, precisePosition = null)
        val expected = GoldenJson.element(
            "binding/GetVehicleResponseTOTest.jsonSample.orientationAngle-90.0.approved.txt",
        )
            .with("transportOrder", null as String?)
            .with("currentPosition", null as String?)
            .with("precisePosition", null as String?)

        V1Json.json.encodeToString(VehicleDto.serializer(), vehicle.toDto()) shouldEqualJsonElement expected
    }
})

private fun sampleVehicle(orientationAngle: Double) = Vehicle(
    name = "some-vehicle",
    properties = linkedMapOf("some-key" to "some-value", "some-other-key" to "some-other-value"),
    boundingBox = BoundingBox(50, 40, 30, Couple(0, 0)),
    energyLevelThresholdSet = EnergyLevelThresholdSet(
        critical = 30,
        good = 90,
        sufficientlyRecharged = 30,
        fullyRecharged = 90,
    ),
    energyLevel = 48,
    integrationLevel = IntegrationLevel.TO_BE_UTILIZED,
    procState = ProcState.PROCESSING_ORDER,
    procStateTimestamp = Instant.parse("2025-01-29T11:41:17Z"),
    transportOrder = "some-order",
    currentPosition = "some-point",
    precisePosition = Position(1, 2, 3),
    orientationAngle = orientationAngle,
    state = VehicleState.EXECUTING,
    stateTimestamp = Instant.parse("2025-01-29T11:48:37Z"),
    allocatedResources = listOf(setOf("some-path", "some-point"), setOf("some-other-path", "some-other-point")),
    claimedResources = listOf(setOf("some-path", "some-point"), setOf("some-other-path", "some-other-point")),
    allowedOrderTypes = setOf("OrderType001", "OrderType002"),
    acceptableOrderTypes = setOf(AcceptableOrderType("OrderType001", 23), AcceptableOrderType("OrderType002", 42)),
    envelopeKey = "envelopeType-01",
)
