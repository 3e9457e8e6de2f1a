package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleLayout
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.orders.HistoryCodes
import java.time.Instant

class ChangedFieldsTest : FunSpec({
    fun parse(bytes: ByteArray) = Json.parseToJsonElement(bytes.decodeToString()).jsonObject

    // What a client subscribed with onlyChanged (and shortenedLists) receives as the event's `current`.
    fun sent(event: KernelEvent): JsonObject = parse(
        WsTopics.change(event)!!.eventBytes(
            1,
            withPrevious = false,
            shortened = Unchanged.shortenedOf(event),
            changed = ChangedFields.of(event),
        ),
    )

    // The client's merge: the state before, the fields sent over it, the shortened lists cut from it.
    fun merged(before: JsonObject, message: JsonObject): JsonObject {
        val fields = before + message["current"]!!.jsonObject
        val cut = message["shortened"]?.jsonObject.orEmpty().mapValues { (name, dropped) ->
            kotlinx.serialization.json.JsonArray(
                before[name]!!.let { it as kotlinx.serialization.json.JsonArray }.drop(dropped.toString().toInt()),
            )
        }
        return JsonObject(fields + cut)
    }

    // kotlinx leaves a null waiting reason out of the whole object; the merge has it as null.
    fun withoutNulls(json: JsonObject) = JsonObject(json.filterValues { it != JsonNull })

    val driving = Vehicle(
        "Vehicle-01",
        state = VehicleState.EXECUTING,
        procState = ProcState.PROCESSING_ORDER,
        integrationLevel = IntegrationLevel.TO_BE_UTILIZED,
        currentPosition = "A",
        precisePosition = Position(0, 0),
        transportOrder = "T1",
        allocatedResources = listOf(setOf("A"), setOf("A-B", "B")),
        claimedResources = listOf(setOf("B-C", "C"), setOf("C-D", "D")),
        waitingReason = "waiting for Vehicle-02",
    )

    test("a vehicle that drove on to its next point is sent as its name, point and pose") {
        val arrived = driving.copy(
            currentPosition = "B",
            precisePosition = Position(2000, 0),
            allocatedResources = driving.allocatedResources.drop(1),
        )

        val message = sent(VehicleEvent(driving, arrived))

        message["current"]!!.jsonObject.keys shouldBe setOf("name", "currentPosition", "pose")
        message["shortened"]!!.jsonObject.keys shouldBe setOf("allocatedResources")
        message.keys.contains("unchanged") shouldBe false
    }

    test("every field of a vehicle that changes reaches the client, a cleared one as null") {
        val changes: List<(Vehicle) -> Vehicle> = listOf(
            { it.copy(properties = mapOf("k" to "v")) },
            { it.copy(boundingBox = BoundingBox(length = 1500)) },
            { it.copy(energyLevelThresholdSet = EnergyLevelThresholdSet(critical = 10)) },
            { it.copy(energyLevel = 55) },
            { it.copy(maxVelocity = 500) },
            { it.copy(maxReverseVelocity = 400) },
            { it.copy(rechargeOperation = "Recharge") },
            { it.copy(loadHandlingDevices = listOf(LoadHandlingDevice("fork", true))) },
            { it.copy(state = VehicleState.IDLE) },
            { it.copy(stateTimestamp = Instant.ofEpochSecond(7)) },
            { it.copy(procState = ProcState.IDLE, procStateTimestamp = Instant.ofEpochSecond(8)) },
            { it.copy(integrationLevel = IntegrationLevel.TO_BE_RESPECTED) },
            { it.copy(paused = true) },
            { it.copy(transportOrder = null) },
            { it.copy(orderSequence = "S1") },
            { it.copy(acceptableOrderTypes = setOf(AcceptableOrderType("Move", 1))) },
            { it.copy(claimedResources = listOf(setOf("B-E", "E"))) },
            { it.copy(claimedResources = it.claimedResources.drop(1)) },
            { it.copy(allocatedResources = it.allocatedResources + listOf(setOf("B-C", "C"))) },
            { it.copy(currentPosition = null) },
            { it.copy(precisePosition = null) },
            { it.copy(orientationAngle = 90.0) },
            { it.copy(envelopeKey = "wide") },
            { it.copy(layout = VehicleLayout("#FF0000")) },
            { it.copy(waitingReason = null) },
            { it.copy(waitingReason = "waiting for Vehicle-03") },
        )
        val before = parse(WsTopics.change(VehicleEvent(null, driving))!!.current!!)

        for (change in changes) {
            val after = change(driving)
            val event = VehicleEvent(driving, after)
            val whole = parse(WsTopics.change(event)!!.current!!)

            withoutNulls(merged(before, sent(event))) shouldBe withoutNulls(whole)
            sent(event)["current"]!!.jsonObject.size shouldBe 1 + ChangedFields.of(event)!!.size -
                Unchanged.shortenedOf(event).size
        }
        val cleared = sent(VehicleEvent(driving, driving.copy(waitingReason = null)))["current"]!!.jsonObject
        cleared["waitingReason"] shouldBe JsonNull
    }

    test("an order advancing a step is sent as its name and step; its waiting reason goes with a new history entry") {
        val order = TransportOrder(
            "T1",
            driveOrders = listOf(DriveOrder("D1", Destination("L1", "Load cargo"))),
            state = TransportOrderState.DISPATCHABLE,
            creationTime = Instant.EPOCH,
        )
        val advanced = order.copy(currentRouteStepIndex = 3)
        val deferred = order.copy(
            history = listOf(HistoryEntry(Instant.EPOCH, HistoryCodes.ORDER_DISPATCHING_DEFERRED, "no vehicle")),
        )

        sent(TransportOrderEvent(order, advanced))["current"]!!.jsonObject.keys shouldBe
            setOf("name", "currentRouteStepIndex")
        val reason: JsonElement = sent(TransportOrderEvent(order, deferred))["current"]!!.jsonObject["waitingReason"]!!
        reason.toString() shouldBe "\"no vehicle\""
        val before = parse(WsTopics.change(TransportOrderEvent(null, deferred))!!.current!!)
        val finished = deferred.copy(state = TransportOrderState.FINISHED, finishedTime = Instant.ofEpochSecond(9))
        val event = TransportOrderEvent(deferred, finished)
        withoutNulls(merged(before, sent(event))) shouldBe withoutNulls(parse(WsTopics.change(event)!!.current!!))
    }

    test("a new or removed object is sent whole, as without onlyChanged") {
        ChangedFields.of(VehicleEvent(null, driving)) shouldBe null
        ChangedFields.of(VehicleEvent(driving, null)) shouldBe null
        sent(
            VehicleEvent(null, driving),
        )["current"] shouldBe parse(WsTopics.change(VehicleEvent(null, driving))!!.current!!)
        sent(VehicleEvent(driving, null))["current"] shouldBe JsonNull
    }
})
