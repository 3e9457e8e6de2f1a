package org.ktcs.kernel.web.ws

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldNotContain
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import org.ktcs.api.model.Vehicle
import org.ktcs.kernel.web.v1.V1Json
import org.ktcs.kernel.web.v1.events.SseVehicleDto
import org.ktcs.kernel.web.v1.events.toSseDto

class EncodedVehiclesTest : FunSpec({
    val vehicle = Vehicle(
        "Fahrzeug-Ä",
        currentPosition = "Punkt-→1",
        claimedResources = listOf(setOf("Punkt-→1 --- Punkt-2", "Punkt-2"), setOf("Punkt-2 --- Punkt-3", "Punkt-3")),
        allocatedResources = listOf(setOf("Punkt-→1")),
        // Keys that look like the resource lists' inside other fields must stay as they are.
        properties = mapOf("claimedResources" to "[]", "note" to "\"allocatedResources\":[]"),
    )

    fun serialized(vehicle: Vehicle) =
        Json.parseToJsonElement(V1Json.json.encodeToString(SseVehicleDto.serializer(), vehicle.toSseDto())).jsonObject

    fun parsed(bytes: ByteArray) = Json.parseToJsonElement(bytes.decodeToString()).jsonObject

    test("a vehicle with its resource lists spliced in as bytes is the JSON the serializer writes") {
        val encoded = EncodedVehicles(8)

        parsed(encoded.marked(vehicle).full) shouldBe serialized(vehicle)
        parsed(encoded.marked(Vehicle("Vehicle-01")).full) shouldBe serialized(Vehicle("Vehicle-01"))
    }

    test("a vehicle without some fields is cut from the marked text: a list left out is not in it") {
        val marked = EncodedVehicles(8).marked(vehicle)
        val whole = serialized(vehicle)

        val withoutClaims = marked.without(listOf("claimedResources", "properties"))
        val withoutBoth = marked.without(listOf("allocatedResources", "claimedResources"))

        parsed(withoutClaims) shouldBe JsonObject(whole - "claimedResources" - "properties")
        withoutClaims.decodeToString() shouldNotContain "Punkt-3"
        parsed(withoutBoth) shouldBe JsonObject(whole - "allocatedResources" - "claimedResources")
    }

    test("a vehicle that moved on keeps its claimed list's bytes, and a changed list is encoded anew") {
        val encoded = EncodedVehicles(8)
        val first = encoded.marked(vehicle)
        val moved = vehicle.copy(currentPosition = "Punkt-2", allocatedResources = listOf(setOf("Punkt-2")))

        parsed(first.full) shouldBe serialized(vehicle)
        parsed(encoded.marked(moved).full) shouldBe serialized(moved)
        parsed(encoded.marked(moved.copy(claimedResources = emptyList())).full) shouldBe
            serialized(moved.copy(claimedResources = emptyList()))
    }
})
