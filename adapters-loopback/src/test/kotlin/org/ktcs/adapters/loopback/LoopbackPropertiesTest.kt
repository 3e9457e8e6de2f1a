package org.ktcs.adapters.loopback

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.loopback.LoopbackProperties.ACCELERATION
import org.ktcs.adapters.loopback.LoopbackProperties.DECELERATION
import org.ktcs.adapters.loopback.LoopbackProperties.LOAD_OPERATION
import org.ktcs.adapters.loopback.LoopbackProperties.OPERATING_TIME
import org.ktcs.adapters.loopback.LoopbackProperties.UNLOAD_OPERATION
import org.ktcs.api.model.Vehicle

class LoopbackPropertiesTest : FunSpec({
    fun parameters(vararg properties: Pair<String, String>) =
        VehicleParameters.of(Vehicle("V", properties = mapOf(*properties)), LoopbackSettings())

    test("without properties a vehicle uses the settings") {
        parameters() shouldBe VehicleParameters(5000, 500.0, 500.0, "Load cargo", "Unload cargo")
    }

    test("properties override the settings; openTCS's negative deceleration counts as braking") {
        parameters(
            OPERATING_TIME to "0",
            ACCELERATION to "250",
            DECELERATION to "-750",
            LOAD_OPERATION to "Pick",
            UNLOAD_OPERATION to "Drop",
        ) shouldBe VehicleParameters(0, 250.0, 750.0, "Pick", "Drop")
    }

    test("unusable numbers fall back to the settings") {
        parameters(OPERATING_TIME to "soon", ACCELERATION to "0", DECELERATION to "NaN") shouldBe parameters()
    }

    test("settings reject values that make no sense") {
        shouldThrow<IllegalArgumentException> { LoopbackSettings(timeFactor = 0.0) }
        shouldThrow<IllegalArgumentException> {
            LoopbackSettings(commandQueueCapacity = 0)
        }
    }
})
