package org.ktcs.kernel.web.v1.orders

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.V1Json

class PostOrderSequenceRequestTest : FunSpec({
    fun decode(json: String) = V1Json.decodeRequest<PostOrderSequenceRequest>(json).toDomain("S-1")

    test("reads openTCS's request sample field by field") {
        val creation = decode(GoldenJson.text("binding/PostOrderSequenceRequestTOTest.jsonSample.approved.txt"))

        creation.name shouldBe "S-1"
        creation.incompleteName shouldBe true
        creation.type shouldBe "Transport"
        creation.orderTypes shouldBe setOf("some-type")
        creation.intendedVehicle shouldBe "some-vehicle"
        creation.failureFatal shouldBe true
        creation.properties shouldBe mapOf("some-key" to "some-value", "another-key" to "another-value")
    }

    test("defaults to any order type and openTCS's default type") {
        val creation = decode("""{"properties":[]}""")

        creation.orderTypes shouldBe setOf("*")
        creation.type shouldBe TransportOrder.DEFAULT_TYPE
        creation.failureFatal shouldBe false
    }

    test("names a property without a value") {
        shouldThrow<InvalidRequestException> { decode("""{"properties":[{"key":"k"}]}""") }
            .message shouldBe "properties[0].value is missing"
    }
})
