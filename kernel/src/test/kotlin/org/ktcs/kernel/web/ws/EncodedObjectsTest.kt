package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.types.shouldBeSameInstanceAs
import kotlinx.serialization.encodeToString
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.web.LastEncoded
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.toSseDto

class EncodedObjectsTest : FunSpec({
    test("an event's previous state reuses the encoding of the event before, and a changed vehicle is encoded anew") {
        val encoded = EncodedObjects()
        val parked = Vehicle("Vehicle-01", currentPosition = "Point-0001")
        val moved = parked.copy(currentPosition = "Point-0002")
        val first = WsTopics.change(VehicleEvent(null, parked), encoded)!!

        val second = WsTopics.change(VehicleEvent(parked, moved), encoded)!!

        second.previous shouldBeSameInstanceAs first.current
        second.current!!.decodeToString() shouldBe V1Json.json.encodeToString(moved.toSseDto())
        second.current!!.decodeToString() shouldNotBe second.previous!!.decodeToString()
    }

    test("an event put together from the states' texts is the message the serializer writes") {
        val parked = Vehicle("Vehicle-01", currentPosition = "Point-0001")
        val change = WsTopics.change(VehicleEvent(parked, parked.copy(currentPosition = null)))!!
        val serialized = V1Json.json.encodeToString(
            WsServerMessage.serializer(),
            WsEvent(
                "vehicles",
                7,
                Json.parseToJsonElement(change.previous!!.decodeToString()),
                Json.parseToJsonElement(change.current!!.decodeToString()),
            ),
        )

        Json.parseToJsonElement(change.eventBytes(7).decodeToString()) shouldBe Json.parseToJsonElement(serialized)
        WsTopics.change(VehicleEvent(null, parked))!!.eventBytes(8).decodeToString() shouldContain "\"previous\":null,"
    }

    test("only the most recently changed objects are kept") {
        var encodings = 0
        val last = LastEncoded<Vehicle, ByteArray>(2) {
            encodings++
            utf8(V1Json.json.encodeToString(it.toSseDto()))
        }
        val vehicles = (1..3).map { Vehicle("Vehicle-0$it") }
        vehicles.forEach { last.of(it.name, it) }

        last.of(vehicles[2].name, vehicles[2])
        last.of(vehicles[0].name, vehicles[0])

        encodings shouldBe 4
    }

    test("a client that wants no previous states gets a removed object's all the same") {
        val parked = Vehicle("Vehicle-01", currentPosition = "Point-0001")
        val moved = WsTopics.change(VehicleEvent(parked, parked.copy(currentPosition = "Point-0002")))!!
        val removed = WsTopics.change(VehicleEvent(parked, null))!!

        fun previousOf(change: Change) =
            Json.parseToJsonElement(change.eventBytes(1, withPrevious = false).decodeToString()).jsonObject["previous"]
        previousOf(moved) shouldBe JsonNull
        previousOf(removed)!!.jsonObject["name"]!!.jsonPrimitive.content shouldBe "Vehicle-01"
    }

    test("text beyond Latin-1 goes on the wire as UTF-8") {
        val vehicle = Vehicle("Fahrzeug-Ä→1")
        val change = WsTopics.change(VehicleEvent(null, vehicle))!!

        change.eventBytes(1).decodeToString() shouldContain "\"name\":\"Fahrzeug-Ä→1\""
    }
})
