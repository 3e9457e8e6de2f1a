package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.loopback.LoopbackFixtures.aToB
import org.ktcs.adapters.loopback.LoopbackFixtures.bToC
import org.ktcs.adapters.loopback.LoopbackFixtures.command
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.VehicleOrientation

class LoopbackDriverMovementTest : FunSpec({
    test("drives a path in the time of its trapezoidal profile, one event per path") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.scheduledActions shouldBe 1
        harness.clock.advanceTo(11_999)
        harness.executedAt() shouldBe emptyList()
        harness.clock.advanceTo(12_000)
        harness.executedAt() shouldContainExactly listOf(12_000L)
    }

    test("drives backward at the lower of the path's and the vehicle's reverse velocity") {
        val harness = Harness()
        harness.message(LoopbackMessages.SET_POSITION, "position" to "B")
        harness.send(command("A--B", "B", "A", orientation = VehicleOrientation.BACKWARD))
        harness.clock.runUntilIdle()
        // min(500, 400) = 400 mm/s: 0.8 s ramps of 160 mm each, 9680 mm cruising in 24.2 s
        harness.executedAt() shouldContainExactly listOf(25_800L)
        // Driving towards -x backwards, the vehicle faces +x.
        harness.context.reportsOf<Report.PrecisePosition>().last() shouldBe
            Report.PrecisePosition(Position(0, 0), 0.0)
    }

    test("a path without a velocity is driven at 100 mm/s, as openTCS does") {
        val harness = Harness()
        harness.send(command("A--S", "A", "S"))
        harness.clock.runUntilIdle()
        // 0.2 s ramps of 10 mm each, 980 mm in 9.8 s
        harness.executedAt() shouldContainExactly listOf(10_200L)
    }

    test("a time factor of 2 halves every duration") {
        val harness = Harness(LoopbackSettings(timeFactor = 2.0, positionReportIntervalMillis = 0))
        harness.send(aToB)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(6_000L)
    }

    test("takes commands up to its queue capacity") {
        val harness = Harness(LoopbackSettings(commandQueueCapacity = 2))
        harness.driver.enqueueCommand(aToB) shouldBe true
        harness.driver.enqueueCommand(bToC) shouldBe true
        harness.driver.canAcceptNextCommand() shouldBe false
        harness.driver.enqueueCommand(command("B--E", "C", "E")) shouldBe false
        harness.clock.advanceTo(11_000)
        harness.driver.canAcceptNextCommand() shouldBe true
    }

    test("on arrival reports the point, then its precise position and heading, then the command executed") {
        val harness = Harness()
        harness.send(aToB)
        val before = harness.context.reports.size
        harness.clock.runUntilIdle()
        harness.context.reports.drop(before) shouldContainExactly listOf(
            Report.PositionReport("B"),
            Report.PrecisePosition(Position(10_000, 0), 0.0),
            Report.Event(LoopbackEvents.COMMAND_FINISHED, mapOf("order" to "T1", "point" to "B", "path" to "A--B")),
            Report.Executed(aToB),
            Report.State(VehicleState.IDLE),
        )
    }

    test("keeps its velocity into an already queued command and faces the direction driven") {
        val harness = Harness()
        harness.send(aToB, bToC)
        harness.clock.runUntilIdle()
        // 2 s ramp + 9 s at 1000 mm/s; then 9 s at 1000 mm/s + 2 s braking
        harness.executedAt() shouldContainExactly listOf(11_000L, 22_000L)
        harness.context.reportsOf<Report.PrecisePosition>().last().angle shouldBe 90.0
    }

    test("a command that arrives while driving keeps the vehicle from braking") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(5_000)
        harness.send(bToC)
        harness.clock.runUntilIdle()
        // No braking on A--B saves 1 s; B--C starts at full speed: 9 s cruising + 2 s braking
        harness.executedAt() shouldContainExactly listOf(11_000L, 22_000L)
        harness.context.timesOf<Report.PrecisePosition>().filter { it > 0 } shouldBe listOf(11_000L, 22_000L)
    }

    test("a vehicle whose timer runs late starts its next step when the timer was due and catches up") {
        for (late in listOf(0L, 1L, 250L, 3_000L)) {
            val harness = Harness()
            harness.send(aToB)
            harness.send(bToC)
            harness.clock.advanceTo(10_999)
            // The kernel thread was busy: A--B's end, due at 11 s, runs at 11 s + late.
            harness.clock.jumpTo(11_000 + late)
            harness.clock.runUntilIdle()
            // B--C still ends at 22 s, as on time; a vehicle that started it late would arrive late as well.
            harness.executedAt() shouldContainExactly listOf(11_000L + late, 22_000L)
        }
    }

    test("a vehicle that waited for its next command does not make up the wait") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(12_000)
        harness.clock.advanceTo(15_000)
        harness.send(bToC)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(12_000L, 27_000L)
    }

    test("a command that arrives after the vehicle reached the end of its path, before its arrival timer fired") {
        for (late in listOf(0L, 1L, 7L, 250L, 3_000L)) {
            val harness = Harness()
            harness.send(aToB)
            harness.clock.advanceTo(11_999)
            harness.clock.jumpTo(12_000 + late)
            harness.send(bToC)
            harness.clock.runUntilIdle()
            harness.context.reportsOf<Report.Executed>() shouldHaveSize 2
        }
    }

    test("a kernel that sends the next command while hearing of the last gets each carried out once") {
        val harness = Harness()
        harness.context.afterExecuted = { if (it == aToB) harness.driver.enqueueCommand(bToC) }
        harness.send(aToB)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(12_000L, 24_000L)
        harness.clock.actionsRun shouldBe 2L
    }

    test("drives back and forth for hours with one scheduled event per path") {
        val harness = Harness()
        val back = command("A--B", "B", "A", orientation = VehicleOrientation.BACKWARD)
        repeat(200) { trip ->
            harness.send(if (trip % 2 == 0) aToB else back)
            harness.clock.runUntilIdle()
        }
        harness.context.reportsOf<Report.Executed>() shouldHaveSize 200
        harness.clock.actionsRun shouldBe 200L
        harness.energies().last() shouldBe 80
    }

    test("is EXECUTING while moving and IDLE when its queue is empty") {
        val harness = Harness()
        harness.send(aToB)
        harness.states().last() shouldBe VehicleState.EXECUTING
        harness.clock.runUntilIdle()
        harness.states() shouldContainExactly listOf(VehicleState.IDLE, VehicleState.EXECUTING, VehicleState.IDLE)
    }

    test("reports precise positions along the path at the configured interval") {
        val harness = Harness(LoopbackSettings(positionReportIntervalMillis = 500))
        harness.send(aToB)
        harness.clock.runUntilIdle()
        val driving = harness.context.timeline.filter { (at, report) -> report is Report.PrecisePosition && at > 0 }
        driving.map { it.first } shouldBe (1..24).map { it * 500L }
        driving.first { it.first == 1_000L }.second shouldBe Report.PrecisePosition(Position(250, 0), 0.0)
        driving.first { it.first == 6_000L }.second shouldBe Report.PrecisePosition(Position(5_000, 0), 0.0)
    }

    test("the report interval is kernel-clock time, whatever the time factor") {
        val harness = Harness(LoopbackSettings(timeFactor = 2.0, positionReportIntervalMillis = 500))
        harness.send(aToB)
        harness.clock.runUntilIdle()
        // 12 s of simulated driving take 6 s of the kernel's clock: a report every 500 ms of it, then the arrival.
        harness.context.timesOf<Report.PrecisePosition>().filter { it > 0 } shouldBe (1..12).map { it * 500L }
    }

    test("at time factor 100 a vehicle sends no more position reports per kernel-clock second than at factor 1") {
        fun reportsPerSecondWhileDriving(timeFactor: Double): Double {
            val harness = Harness(LoopbackSettings(timeFactor = timeFactor, positionReportIntervalMillis = 500))
            harness.send(aToB)
            harness.clock.runUntilIdle()
            val arrival = harness.executedAt().single()
            val between = harness.context.timesOf<Report.PrecisePosition>().count { it in 1 until arrival }
            return between * 1000.0 / arrival
        }
        val atFactor1 = reportsPerSecondWhileDriving(1.0)
        atFactor1 shouldBe 23 * 1000.0 / 12_000
        reportsPerSecondWhileDriving(100.0) shouldBeLessThanOrEqual atFactor1
    }

    test("reports precise positions only at points when the interval is 0") {
        val harness = Harness(LoopbackSettings(positionReportIntervalMillis = 0))
        harness.send(aToB)
        harness.clock.runUntilIdle()
        harness.context.timesOf<Report.PrecisePosition>().filter { it > 0 } shouldHaveSize 1
    }

    test("fails a command whose path is not in the model and goes on") {
        val harness = Harness()
        val ghost = command("nowhere", "A", "B")
        harness.send(ghost, aToB)
        harness.clock.runUntilIdle()
        harness.context.reportsOf<Report.Failed>() shouldContainExactly listOf(Report.Failed(ghost))
        harness.context.reportsOf<Report.Executed>() shouldContainExactly listOf(Report.Executed(aToB))
        harness.notifications().single() shouldBe "V: path nowhere is not in the plant model; command for T1 failed"
    }
})
