package org.ktcs.kernel.web.v1.plantmodel

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.model.VisualLayout
import org.ktcs.kernel.web.v1.V1Json

class PlantModelValidationTest : FunSpec({
    fun rejection(json: String) =
        shouldThrow<InvalidRequestException> { V1Json.decodeRequest<PlantModelDto>(json).toDomain() }.message

    test("accepts a model with only a name and falls back to defaults") {
        val model = V1Json.decodeRequest<PlantModelDto>("""{"name":"m"}""").toDomain()

        model.points shouldBe emptyList()
        model.visualLayout shouldBe VisualLayout()
    }

    test("names a missing model or element name") {
        rejection("""{"points":[]}""") shouldBe "name is missing"
        rejection("""{"name":"m","points":[{"name":"A"},{}]}""") shouldBe "points[1].name is missing"
    }

    test("names a missing path end") {
        rejection("""{"name":"m","paths":[{"name":"P","srcPointName":"A"}]}""") shouldBe
            "paths[0].destPointName is missing"
    }

    test("names an unknown enum value and lists the allowed ones") {
        rejection("""{"name":"m","points":[{"name":"A","type":"REPORT_POSITION"}]}""") shouldBe
            "points[0].type has unknown value 'REPORT_POSITION', expected one of HALT_POSITION, PARK_POSITION"
        rejection("""{"name":"m","blocks":[{"name":"B","type":"ANY"}]}""") shouldBe
            "blocks[0].type has unknown value 'ANY', expected one of SINGLE_VEHICLE_ONLY, SAME_DIRECTION_ONLY"
    }

    test("names a bad location link, layout or energy level") {
        rejection("""{"name":"m","locations":[{"name":"L","typeName":"T","links":[{}]}]}""") shouldBe
            "locations[0].links[0].pointName is missing"
        rejection("""{"name":"m","locations":[{"name":"L","typeName":"T","layout":{"locationRepresentation":"X"}}]}""")
            ?.startsWith("locations[0].layout.locationRepresentation has unknown value 'X'") shouldBe true
        rejection("""{"name":"m","vehicles":[{"name":"V","energyLevelGood":101}]}""") shouldBe
            "vehicles[0].energyLevelGood must be within 0..100, was 101"
    }

    test("names a property without a name") {
        rejection("""{"name":"m","properties":[{"value":"v"}]}""") shouldBe "properties[0].name is missing"
    }
})
