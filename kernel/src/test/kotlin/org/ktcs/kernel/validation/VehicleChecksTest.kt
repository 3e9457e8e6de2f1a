package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.datatest.withTests
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.BoundingBox
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.Envelope
import org.ktcs.api.model.PlantModel

private const val VEHICLE = "vehicle 'Vehicle-01'"

private data class OutOfRange(val name: String, val value: Int, val thresholds: EnergyLevelThresholdSet)

private fun withThresholds(critical: Int, good: Int, sufficientlyRecharged: Int, fullyRecharged: Int): PlantModel =
    minimalPlant().mapVehicles {
        it.copy(
            energyLevelThresholdSet = EnergyLevelThresholdSet(critical, good, sufficientlyRecharged, fullyRecharged),
        )
    }

class VehicleChecksTest : FunSpec({
    context("energy thresholds") {
        test("openTCS's demo thresholds are fine") {
            withThresholds(30, 90, 45, 95).problems().shouldBeEmpty()
        }

        test("equal thresholds are fine") {
            withThresholds(50, 50, 50, 50).problems().shouldBeEmpty()
        }

        withTests(
            nameFn = { "${it.name} of ${it.value} is out of range" },
            OutOfRange("critical", -1, EnergyLevelThresholdSet(-1, 90, 30, 90)),
            OutOfRange("good", 101, EnergyLevelThresholdSet(30, 101, 30, 90)),
            OutOfRange("sufficientlyRecharged", -5, EnergyLevelThresholdSet(0, 90, -5, 90)),
            OutOfRange("fullyRecharged", 200, EnergyLevelThresholdSet(30, 90, 30, 200)),
        ) { (name, value, thresholds) ->
            val model = minimalPlant().mapVehicles { it.copy(energyLevelThresholdSet = thresholds) }

            model.errors() shouldBe
                listOf(expectedError(VEHICLE, "energy level $name must be within 0..100, was $value"))
        }

        test("critical above good is an error") {
            withThresholds(60, 50, 60, 90).problems() shouldBe
                listOf(expectedError(VEHICLE, "energy level critical (60) must not exceed good (50)"))
        }

        test("sufficientlyRecharged above fullyRecharged is an error") {
            withThresholds(30, 90, 95, 90).problems() shouldBe listOf(
                expectedError(VEHICLE, "energy level sufficientlyRecharged (95) must not exceed fullyRecharged (90)"),
            )
        }

        test("critical above sufficientlyRecharged is only a warning, because openTCS accepts it") {
            withThresholds(40, 90, 30, 90).problems() shouldBe listOf(
                expectedWarning(
                    VEHICLE,
                    "energy level critical (40) exceeds sufficientlyRecharged (30): " +
                        "a charging vehicle would count as sufficiently recharged while still critical",
                ),
            )
        }
    }

    test("a negative maxVelocity is an error") {
        minimalPlant().mapVehicles { it.copy(maxVelocity = -100) }.problems() shouldBe
            listOf(expectedError(VEHICLE, "maxVelocity must not be negative, was -100"))
    }

    test("a negative maxReverseVelocity is an error") {
        minimalPlant().mapVehicles { it.copy(maxReverseVelocity = -1) }.problems() shouldBe
            listOf(expectedError(VEHICLE, "maxReverseVelocity must not be negative, was -1"))
    }

    test("a vehicle that cannot drive at all is fine") {
        minimalPlant().mapVehicles { it.copy(maxVelocity = 0, maxReverseVelocity = 0) }.problems().shouldBeEmpty()
    }

    test("each non-positive bounding-box dimension is an error") {
        val model = minimalPlant().mapVehicles {
            it.copy(boundingBox = BoundingBox(length = 0, width = -1, height = 500))
        }

        model.problems() shouldBe listOf(
            expectedError(VEHICLE, "bounding box length must be positive, was 0"),
            expectedError(VEHICLE, "bounding box width must be positive, was -1"),
        )
    }

    test("an envelope key that a point or a path defines is fine") {
        val envelope = Envelope(emptyList())
        val onPoint = minimalPlant().mapPoints { it.copy(vehicleEnvelopes = mapOf("small" to envelope)) }
        val onPath = minimalPlant().mapPaths { it.copy(vehicleEnvelopes = mapOf("small" to envelope)) }

        onPoint.mapVehicles { it.copy(envelopeKey = "small") }.problems().shouldBeEmpty()
        onPath.mapVehicles { it.copy(envelopeKey = "small") }.problems().shouldBeEmpty()
    }

    test("an envelope key nothing defines is only a warning") {
        minimalPlant().mapVehicles { it.copy(envelopeKey = "huge") }.problems() shouldBe
            listOf(expectedWarning(VEHICLE, "envelope key 'huge' is defined by no point or path"))
    }
})
