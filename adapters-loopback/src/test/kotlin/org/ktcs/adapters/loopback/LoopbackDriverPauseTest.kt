package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.loopback.LoopbackFixtures.aToB
import org.ktcs.adapters.loopback.LoopbackFixtures.bToC
import org.ktcs.adapters.loopback.LoopbackFixtures.command

class LoopbackDriverPauseTest : FunSpec({
    test("a pause freezes the trip and the resumed vehicle needs only the remaining time") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(4_000)
        harness.driver.onPaused(true)
        harness.clock.advanceTo(100_000)
        harness.executedAt() shouldBe emptyList()
        harness.driver.onPaused(false)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(108_000L)
    }

    test("a paused vehicle reports no positions") {
        val harness = Harness(LoopbackSettings(positionReportIntervalMillis = 500))
        harness.send(aToB)
        harness.clock.advanceTo(4_200)
        harness.driver.onPaused(true)
        val reports = harness.context.reports.size
        harness.clock.advanceTo(50_000)
        harness.context.reports.size shouldBe reports
        harness.driver.onPaused(false)
        harness.clock.advanceTo(50_300)
        harness.context.timesOf<Report.PrecisePosition>().last() shouldBe 50_300L
    }

    test("commands sent while paused wait for the resume") {
        val harness = Harness()
        harness.driver.onPaused(true)
        harness.send(aToB)
        harness.clock.advanceTo(60_000)
        harness.executedAt() shouldBe emptyList()
        harness.driver.onPaused(false)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(72_000L)
    }

    test("a pause freezes an operation too") {
        val harness = Harness()
        harness.send(command("A--B", "A", "B", "Inspect", "Station"))
        harness.clock.advanceTo(13_000)
        harness.driver.onPaused(true)
        harness.clock.advanceTo(40_000)
        harness.driver.onPaused(false)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(44_000L)
    }

    test("a vehicle paused in the kernel starts paused") {
        val harness = Harness(enable = false)
        harness.context.updateVehicle { it.copy(paused = true) }
        harness.driver.enable()
        harness.send(aToB, bToC)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldBe emptyList()
    }
})
