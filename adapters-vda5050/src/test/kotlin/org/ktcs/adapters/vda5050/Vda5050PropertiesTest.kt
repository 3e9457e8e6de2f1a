package org.ktcs.adapters.vda5050

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain

/**
 * The vehicle properties with openTCS's keys and defaults, as openTCS's documentation of its VDA 5050 2.0 driver
 * lists them ("Driver configuration", CC-BY-4.0, The openTCS Authors).
 */
class Vda5050PropertiesTest : FunSpec({
    val required = vdaProperties("AGV-XY-1234") + ("vda5050:manufacturer" to "Some_Company")

    test("the defaults of openTCS's property table") {
        val p = Vda5050Properties.read("V1", required)
        p.topicPrefix shouldBe "uagv/v2/Some_Company/AGV-XY-1234"
        listOf(p.connection, p.state, p.visualization, p.factsheet, p.order, p.instantActions) shouldBe listOf(
            TopicSetting("connection", 0),
            TopicSetting("state", 0),
            TopicSetting("visualization", 0),
            TopicSetting("factsheet", 0),
            TopicSetting("order", 0),
            TopicSetting("instantActions", 0),
        )
        p.validateIncomingMessages shouldBe true
        p.rechargeOperation shouldBe "Charge"
        p.maxStepsBase shouldBe 2
        p.maxDistanceBase shouldBe Long.MAX_VALUE
        p.maxStepsHorizon shouldBe Int.MAX_VALUE
        p.minVisualizationIntervalMillis shouldBe 500
        p.completion shouldBe CompletionCondition.EDGE_AND_NODE
        p.maxIgnoredRejections shouldBe 0
        p.vehicleLengthLoaded shouldBe null
        p.lastNodeIdRequired shouldBe false
    }

    test("every setting of openTCS's table is read") {
        val p = Vda5050Properties.read(
            "V1",
            required + mapOf(
                "vda5050:topicPrefix" to "myprefix",
                "vda5050:topicStateName" to "st",
                "vda5050:topicStateQos" to "at_least_once",
                "vda5050:topicOrderQos" to "2",
                "vda5050:validateIncomingMessages" to "false",
                "vda5050:rechargeOperation" to "Recharge",
                "vda5050:maxStepsBase" to "10",
                "vda5050:maxStepsHorizon" to "3",
                "vda5050:minVisualizationInterval" to "1000",
                "vda5050:vehicleLengthLoaded" to "1500",
                "vda5050:movementCommandCompletedCondition" to "EDGE",
                "vda5050:maxIgnoredRejections" to "2",
                "vda5050:maxDistanceBase" to "5000",
                "vda5050:vehicleLengthUnloaded" to "900",
                "vda5050:lastNodeIdRequiredForMovementCompletion" to "true",
            ),
        )
        p.topicPrefix shouldBe "myprefix"
        p.topic(p.state) shouldBe "myprefix/st"
        p.state.qos shouldBe 1
        p.order.qos shouldBe 2
        p.validateIncomingMessages shouldBe false
        p.rechargeOperation shouldBe "Recharge"
        p.maxStepsBase shouldBe 10
        p.maxStepsHorizon shouldBe 3
        p.minVisualizationIntervalMillis shouldBe 1000
        p.vehicleLengthLoaded shouldBe 1500
        p.completion shouldBe CompletionCondition.EDGE
        p.maxIgnoredRejections shouldBe 2
        p.maxDistanceBase shouldBe 5000L
        p.vehicleLengthUnloaded shouldBe 900
        p.lastNodeIdRequired shouldBe true
    }

    test("a missing or unusable property names the vehicle and the property") {
        shouldThrow<IllegalArgumentException> { Vda5050Properties.read("V1", required - "vda5050:serialNumber") }
            .message shouldBe "vehicle V1: property vda5050:serialNumber is missing"
        shouldThrow<IllegalArgumentException> {
            Vda5050Properties.read("V1", required - "vda5050:interfaceName")
        }.message shouldContain "vda5050:topicPrefix is missing"
        shouldThrow<IllegalArgumentException> { Vda5050Properties.read("V1", required + ("vda5050:version" to "1.1")) }
            .message shouldContain "vda5050:version must be one of 2.0, 2.1, was '1.1'"
        shouldThrow<IllegalArgumentException> {
            Vda5050Properties.read("V1", required + ("vda5050:maxStepsBase" to "0"))
        }.message shouldContain "vda5050:maxStepsBase must be a whole number of at least 1, was '0'"
        shouldThrow<IllegalArgumentException> {
            Vda5050Properties.read("V1", required + ("vda5050:topicStateQos" to "sometimes"))
        }.message shouldContain "vda5050:topicStateQos must be"
    }
})
