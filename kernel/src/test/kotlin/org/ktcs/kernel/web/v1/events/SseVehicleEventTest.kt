package org.ktcs.kernel.web.v1.events

import io.kotest.core.spec.style.FunSpec
import kotlinx.serialization.json.JsonArray
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.Couple
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VehicleState
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.inBothStates
import org.ktcs.kernel.web.v1.with
import java.time.Instant

class SseVehicleEventTest : FunSpec({
    test("encodes a vehicle change as openTCS's SSE sample, apart from the history kTCS does not keep") {
        val event = VehicleEvent(
            previous = sampleVehicle(IntegrationLevel.TO_BE_RESPECTED),
            current = sampleVehicle(IntegrationLevel.TO_BE_UTILIZED),
        )
        val expected = GoldenJson.element("binding/sse/VehicleEventTOTest.jsonSample.approved.txt")
            .inBothStates { with("$it.history.entries", JsonArray(emptyList())) }

        V1Json.json.encodeToString(
            ObjectEventDto.serializer(SseVehicleDto.serializer()),
            event.toDto(),
        ) shouldEqualJsonElement
            expected
    }
})

private val AT_12_03 = Instant.parse("2025-07-22T12:03:00Z")

private fun sampleVehicle(integrationLevel: IntegrationLevel) = Vehicle(
    name = "vehicle-1",
    properties = linkedMapOf("key-1" to "value-1", "key-2" to "value-2"),
    boundingBox = BoundingBox(1, 2, 3, Couple(4, 5)),
    energyLevelThresholdSet = EnergyLevelThresholdSet(
        critical = 1,
        good = 2,
        sufficientlyRecharged = 3,
        fullyRecharged = 4,
    ),
    energyLevel = 42,
    maxVelocity = 200,
    maxReverseVelocity = 100,
    rechargeOperation = "recharge-operation",
    loadHandlingDevices = listOf(LoadHandlingDevice("lhd-1", true)),
    state = VehicleState.IDLE,
    stateTimestamp = AT_12_03,
    procState = ProcState.IDLE,
    procStateTimestamp = AT_12_03,
    integrationLevel = integrationLevel,
    paused = true,
    transportOrder = "transport-order-1",
    orderSequence = "order-sequence-1",
    acceptableOrderTypes = setOf(
        AcceptableOrderType("acceptable-order-type-1", 2),
        AcceptableOrderType("acceptable-order-type-2", 5),
    ),
    claimedResources = listOf(setOf("resource-1", "resource-2")),
    allocatedResources = listOf(setOf("resource-3", "resource-4"), setOf("resource-5", "resource-6")),
    currentPosition = "position-1",
    precisePosition = Position(1, 2, 3),
    orientationAngle = 4.5,
    envelopeKey = "envelope-key-1",
    layout = VehicleLayout(routeColor = "#3C1428"),
)
