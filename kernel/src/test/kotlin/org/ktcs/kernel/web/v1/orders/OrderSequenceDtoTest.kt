package org.ktcs.kernel.web.v1.orders

import io.kotest.core.spec.style.FunSpec
import org.ktcs.api.order.OrderSequence
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.GoldenJson.shouldEqualJsonElement
import org.ktcs.kernel.web.v1.V1Json
import java.time.Instant

class OrderSequenceDtoTest : FunSpec({
    test("encodes an unfinished order sequence exactly as openTCS's GET sample") {
        val sequence = OrderSequence(
            name = "some-order-sequence",
            creationTime = Instant.EPOCH,
            type = "Charge",
            orderTypes = setOf("some-type", "some-other-type"),
            orders = listOf("some-order", "another-order", "order-3"),
            finishedIndex = 3,
            failureFatal = true,
            intendedVehicle = "some-vehicle",
            properties = linkedMapOf("some-key" to "some-value", "another-key" to "another-value"),
        )

        V1Json.json.encodeToString(OrderSequenceDto.serializer(), sequence.toDto()) shouldEqualJsonElement
            GoldenJson.element("binding/GetOrderSequenceResponseTOTest.jsonSample.approved.txt")
    }
})
