package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldNotContain
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.TransportOrder
import java.time.Instant

class UnchangedTest : FunSpec({
    fun parse(bytes: ByteArray) = Json.parseToJsonElement(bytes.decodeToString()).jsonObject

    test("fields are cut from the top level only, whatever their values hold") {
        val json = """{"a":"x\"y,}","b":{"a":[1,{"b":2}],"c":"]"},"c":[[1],[2]],"d":null,"e":-1.5e3,"f":true}"""

        parse(withoutFields(utf8(json), listOf("b", "d", "f"))) shouldBe
            Json.parseToJsonElement("""{"a":"x\"y,}","c":[[1],[2]],"e":-1.5e3}""")
        parse(withoutFields(utf8(json), listOf("a"))).keys shouldBe setOf("b", "c", "d", "e", "f")
        parse(withoutFields(utf8(json), listOf("f"))).keys shouldBe setOf("a", "b", "c", "d", "e")
        withoutFields(utf8(json), emptyList()).decodeToString() shouldBe json
    }

    test("an order advancing a step leaves out its drive orders; the client puts back the same object") {
        val order = TransportOrder(
            "T1",
            driveOrders = listOf(DriveOrder("D1", Destination("L1", "Load cargo"))),
            creationTime = Instant.EPOCH,
        )
        val advanced = order.copy(currentRouteStepIndex = 3)
        val event = TransportOrderEvent(order, advanced)
        val change = WsTopics.change(event)!!

        val message = parse(change.eventBytes(5, withPrevious = false, Unchanged.fieldsOf(event)))

        val unchanged = message["unchanged"]!!.jsonArray.map { it.jsonPrimitive.content }
        unchanged shouldBe listOf(
            "driveOrders",
            "properties",
            "history",
            "dependencies",
            "creationTime",
            "deadline",
            "finishedTime",
        )
        val current = message["current"]!!.jsonObject
        current.keys.intersect(unchanged.toSet()) shouldBe emptySet()
        current["currentRouteStepIndex"]!!.jsonPrimitive.content shouldBe "3"
        val before = parse(change.previous!!)
        JsonObject(before + current) shouldBe parse(change.current!!)
    }

    test("a vehicle whose resources changed gets them in full; a new or removed object is never cut") {
        val parked = Vehicle("Vehicle-01", currentPosition = "A", allocatedResources = listOf(setOf("A")))
        val moving = parked.copy(allocatedResources = listOf(setOf("A"), setOf("A-B", "B")))

        val stable = listOf(
            "properties",
            "acceptableOrderTypes",
            "boundingBox",
            "energyLevelThresholdSet",
            "loadHandlingDevices",
            "state",
            "procState",
            "layout",
        )
        Unchanged.fieldsOf(VehicleEvent(parked, moving)) shouldBe listOf("claimedResources") + stable
        Unchanged.fieldsOf(VehicleEvent(null, parked)) shouldBe emptyList()
        // A state is its value and its timestamp: the same state entered again is a change.
        val again = moving.copy(stateTimestamp = Instant.ofEpochSecond(5))
        Unchanged.fieldsOf(VehicleEvent(moving, again)) shouldBe
            listOf("claimedResources", "allocatedResources") + (stable - "state")
        val removed = WsTopics.change(VehicleEvent(parked, null))!!
        parse(removed.eventBytes(1, unchanged = listOf("properties")))["unchanged"] shouldBe null
    }

    test("a resource list that lost its first steps is named with how many; any other change is not") {
        val steps = listOf(setOf("A-B", "B"), setOf("B-C", "C"), setOf("C-D", "D"))
        val driving = Vehicle("Vehicle-01", currentPosition = "A", claimedResources = steps)
        val granted = driving.copy(claimedResources = steps.drop(1), allocatedResources = listOf(setOf("A-B", "B")))
        val rerouted = driving.copy(claimedResources = listOf(setOf("A-E", "E")) + steps.drop(1))

        Unchanged.shortenedOf(VehicleEvent(driving, granted)) shouldBe mapOf("claimedResources" to 1)
        Unchanged.shortenedOf(VehicleEvent(driving, driving.copy(claimedResources = emptyList()))) shouldBe
            mapOf("claimedResources" to 3)
        Unchanged.shortenedOf(VehicleEvent(driving, rerouted)) shouldBe emptyMap()
        Unchanged.shortenedOf(VehicleEvent(driving, driving)) shouldBe emptyMap()
        Unchanged.shortenedOf(VehicleEvent(null, driving)) shouldBe emptyMap()

        val message = parse(
            WsTopics.change(VehicleEvent(driving, granted))!!.eventBytes(
                2,
                withPrevious = false,
                Unchanged.fieldsOf(VehicleEvent(driving, granted)),
                Unchanged.shortenedOf(VehicleEvent(driving, granted)),
            ),
        )
        message["shortened"]!!.jsonObject["claimedResources"]!!.jsonPrimitive.content shouldBe "1"
        val current = message["current"]!!.jsonObject
        current.keys shouldNotContain "claimedResources"
        current["allocatedResources"]!!.jsonArray.size shouldBe 1
    }
})
