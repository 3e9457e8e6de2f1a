package org.ktcs.kernel.web.v1.orders

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.V1Json
import java.time.Instant

class PostTransportOrderRequestTest : FunSpec({
    fun decode(json: String) = V1Json.decodeRequest<PostTransportOrderRequest>(json).toDomain("T-1")

    fun rejection(json: String) = shouldThrow<InvalidRequestException> { decode(json) }.message

    test("reads openTCS's request sample field by field") {
        val creation = decode(GoldenJson.text("binding/PostTransportOrderRequestTOTest.jsonSample.approved.txt"))

        creation.name shouldBe "T-1"
        creation.incompleteName shouldBe true
        creation.dispensable shouldBe true
        creation.deadline shouldBe Instant.EPOCH
        creation.intendedVehicle shouldBe "some-vehicle"
        creation.peripheralReservationToken shouldBe "some-token"
        creation.wrappingSequence shouldBe "some-sequence"
        creation.type shouldBe "some-type"
        creation.destinations shouldBe listOf(
            Destination(
                "some-location",
                "some-operation",
                mapOf("some-key" to "some-value", "some-other-key" to "some-other-value"),
            ),
        )
        creation.properties shouldBe mapOf("some-key" to "some-value", "some-other-key" to "some-other-value")
        creation.dependencies shouldBe setOf("some-other-order", "another-order")
    }

    test("fills absent optional fields with openTCS's defaults") {
        val creation = decode("""{"destinations":[{"locationName":"L","operation":"Load"}]}""")

        creation.type shouldBe TransportOrder.DEFAULT_TYPE
        creation.deadline shouldBe Instant.MAX
        creation.intendedVehicle shouldBe null
        creation.incompleteName shouldBe false
        creation.dependencies shouldBe emptySet()
        creation.properties shouldBe emptyMap()
    }

    test("names a missing operation with its destination index") {
        rejection(
            """{"destinations":[{"locationName":"A","operation":"Load"},{"locationName":"B"}]}""",
        ) shouldBe "destinations[1].operation is missing"
    }

    test("names a missing location name") {
        rejection("""{"destinations":[{"operation":"Load"}]}""") shouldBe "destinations[0].locationName is missing"
    }

    test("rejects missing and empty destinations") {
        rejection("""{"type":"t"}""") shouldBe "destinations is missing"
        rejection("""{"destinations":[]}""") shouldBe "destinations must not be empty"
    }

    test("rejects a deadline that is not an ISO-8601 timestamp") {
        rejection("""{"deadline":"tomorrow","destinations":[{"locationName":"A","operation":"Load"}]}""") shouldBe
            "deadline is not an ISO-8601 timestamp: 'tomorrow'"
    }

    test("rejects a property without a key") {
        rejection(
            """{"destinations":[{"locationName":"A","operation":"Load","properties":[{"value":"v"}]}]}""",
        ) shouldBe "destinations[0].properties[0].key is missing"
    }

    test("rejects malformed JSON, wrongly typed and unknown fields, as openTCS's Jackson setup does") {
        rejection("""{"destinations":""")
        rejection("""{"priority":1,"destinations":[{"locationName":"A","operation":"Load"}]}""")
        rejection("""{"dispensable":"maybe","destinations":[{"locationName":"A","operation":"Load"}]}""")
    }
})
