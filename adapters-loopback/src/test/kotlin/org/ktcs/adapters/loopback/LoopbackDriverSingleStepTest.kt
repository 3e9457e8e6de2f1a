package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.loopback.LoopbackFixtures.aToB
import org.ktcs.adapters.loopback.LoopbackFixtures.bToC
import org.ktcs.api.model.VehicleState

class LoopbackDriverSingleStepTest : FunSpec({
    fun singleStep() = Harness().apply {
        message(LoopbackMessages.SET_SINGLE_STEP_MODE_ENABLED, "value" to "true")
        driver.isSingleStepModeEnabled shouldBe true
    }

    test("in single-step mode each command waits for a trigger") {
        val harness = singleStep()
        harness.send(aToB, bToC)
        harness.clock.advanceTo(60_000)
        harness.executedAt() shouldBe emptyList()
        harness.message(LoopbackMessages.TRIGGER_SINGLE_STEP)
        harness.clock.runUntilIdle()
        // Stepping, the vehicle stops at the end of each command.
        harness.executedAt() shouldContainExactly listOf(72_000L)
        harness.states().last() shouldBe VehicleState.IDLE
        harness.message(LoopbackMessages.TRIGGER_SINGLE_STEP)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(72_000L, 84_000L)
    }

    test("a trigger while the vehicle is busy or outside single-step mode does nothing") {
        val harness = Harness()
        harness.send(aToB)
        harness.message(LoopbackMessages.TRIGGER_SINGLE_STEP)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(12_000L)
        harness.notifications() shouldBe emptyList()
    }

    test("leaving single-step mode carries on with the waiting commands") {
        val harness = singleStep()
        harness.send(aToB, bToC)
        harness.message(LoopbackMessages.SET_SINGLE_STEP_MODE_ENABLED, "enabled" to "false")
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(11_000L, 22_000L)
    }
})
