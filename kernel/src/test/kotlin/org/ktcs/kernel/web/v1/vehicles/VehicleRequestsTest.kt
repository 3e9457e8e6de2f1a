package org.ktcs.kernel.web.v1.vehicles

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.kernel.web.v1.GoldenJson
import org.ktcs.kernel.web.v1.V1Json

class VehicleRequestsTest : FunSpec({
    test("reads openTCS's allowed order types sample") {
        val text = GoldenJson.text("binding/PutVehicleAllowedOrderTypesTOTest.jsonSample.approved.txt")

        V1Json.decodeRequest<PutAllowedOrderTypesRequest>(text).toDomain() shouldBe
            setOf("some-orderType", "another-orderType", "orderType-3")
    }

    test("reads openTCS's acceptable order types sample") {
        val text = GoldenJson.text("binding/PutVehicleAcceptableOrderTypesTOTest.jsonSample.approved.txt")

        V1Json.decodeRequest<PutAcceptableOrderTypesRequest>(text).toDomain() shouldBe setOf(
            AcceptableOrderType("some-orderType", 0),
            AcceptableOrderType("another-orderType", 1),
            AcceptableOrderType("orderType-3", 2),
        )
    }

    test("reads openTCS's comm adapter message sample") {
        val text = GoldenJson.text("binding/PostVehicleCommAdapterMessageRequestTOTest.jsonSample.approved.txt")

        V1Json.decodeRequest<PostCommAdapterMessageRequest>(text).toDomain() shouldBe
            DriverMessage("some-type", mapOf("key1" to "value1", "key2" to "value2"))
    }

    test("reads an energy level threshold set") {
        val json = """{"energyLevelCritical":10,"energyLevelGood":80,"energyLevelSufficientlyRecharged":40,
            |"energyLevelFullyRecharged":95}
        """.trimMargin()

        V1Json.decodeRequest<PutEnergyLevelThresholdSetRequest>(json).toDomain() shouldBe
            EnergyLevelThresholdSet(critical = 10, good = 80, sufficientlyRecharged = 40, fullyRecharged = 95)
    }

    test("rejects a threshold outside 0..100 and a missing one, naming the field") {
        fun rejection(json: String) = shouldThrow<InvalidRequestException> {
            V1Json.decodeRequest<PutEnergyLevelThresholdSetRequest>(json).toDomain()
        }.message

        rejection(
            """{"energyLevelCritical":10,"energyLevelGood":180,"energyLevelSufficientlyRecharged":40,
            |"energyLevelFullyRecharged":95}
            """.trimMargin(),
        ) shouldBe "energyLevelGood must be within 0..100, was 180"
        rejection("""{"energyLevelCritical":10}""") shouldBe "energyLevelGood is missing"
    }

    test("names missing fields of order type and message requests") {
        shouldThrow<InvalidRequestException> {
            V1Json.decodeRequest<PutAllowedOrderTypesRequest>("{}").toDomain()
        }.message shouldBe "orderTypes is missing"
        shouldThrow<InvalidRequestException> {
            V1Json.decodeRequest<PutAcceptableOrderTypesRequest>(
                """{"acceptableOrderTypes":[{"name":"x"}]}""",
            ).toDomain()
        }.message shouldBe "acceptableOrderTypes[0].priority is missing"
        shouldThrow<InvalidRequestException> {
            V1Json.decodeRequest<PostCommAdapterMessageRequest>("""{"parameters":[]}""").toDomain()
        }.message shouldBe "type is missing"
    }
})
