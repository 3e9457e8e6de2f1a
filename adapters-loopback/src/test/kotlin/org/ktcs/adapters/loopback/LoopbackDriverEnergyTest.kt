package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.adapters.loopback.LoopbackFixtures.bToE
import org.ktcs.adapters.loopback.LoopbackFixtures.command
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState

class LoopbackDriverEnergyTest : FunSpec({
    val charge = command("B--C", "B", "C", "CHARGE", "Charger")

    fun atB(energy: Int = 100, settings: LoopbackSettings = LoopbackSettings(positionReportIntervalMillis = 0)) =
        Harness(settings, LoopbackFixtures.vehicle(LoopbackProperties.INITIAL_POSITION to "B", energy = energy))

    test("driving 1 km at 10 %/km uses 10 % of the battery") {
        val harness = atB()
        harness.send(bToE)
        harness.clock.runUntilIdle()
        harness.energies() shouldContainExactly listOf(100, 90)
    }

    test("reports the energy falling whole percent by whole percent while driving") {
        val harness = atB(settings = LoopbackSettings(positionReportIntervalMillis = 10_000))
        harness.send(bToE)
        harness.clock.runUntilIdle()
        harness.energies() shouldBe (100 downTo 90).toList()
    }

    test("a vehicle with no drain never discharges, like openTCS's loopback") {
        val harness = atB(settings = LoopbackSettings(energyDrainPercentPerKm = 0.0, positionReportIntervalMillis = 0))
        harness.send(bToE)
        harness.clock.runUntilIdle()
        harness.energies() shouldContainExactly listOf(100)
    }

    test("an empty battery stops the vehicle with ERROR, a notification and the command failed") {
        val harness = atB(energy = 5)
        harness.send(bToE)
        harness.clock.runUntilIdle()
        // 5 % last 500 m: 2 s of acceleration (1000 mm), then 499 s at 1000 mm/s
        harness.context.timesOf<Report.Failed>() shouldContainExactly listOf(501_000L)
        harness.context.reportsOf<Report.Failed>().single().command shouldBe bToE
        harness.states().last() shouldBe VehicleState.ERROR
        harness.energies().last() shouldBe 0
        harness.context.reportsOf<Report.PrecisePosition>().last().position shouldBe Position(510_000, 0)
        val notification = harness.context.reportsOf<Report.Notification>().single()
        notification.level shouldBe NotificationLevel.IMPORTANT
        notification.text shouldContain "battery empty"
        harness.executedAt() shouldBe emptyList()
    }

    test("a stranded vehicle waits for energy, then carries on with its commands") {
        val harness = atB(energy = 1)
        harness.send(bToE)
        harness.clock.runUntilIdle()
        val next = command("B--E", "B", "E", order = "T2")
        harness.send(next)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldBe emptyList()
        harness.message(LoopbackMessages.SET_ENERGY_LEVEL, "value" to "50")
        harness.states().last() shouldBe VehicleState.EXECUTING
        harness.clock.runUntilIdle()
        harness.context.reportsOf<Report.Executed>().single().command shouldBe next
    }

    test("setting the energy while driving moves the point where the battery runs empty") {
        val harness = atB(energy = 5)
        harness.send(bToE)
        harness.clock.advanceTo(100_000)
        harness.message(LoopbackMessages.SET_ENERGY_LEVEL, "value" to "100")
        harness.clock.runUntilIdle()
        harness.executedAt() shouldContainExactly listOf(1_002_000L)
    }

    test("the recharge operation charges until 100 % and reports the command after the operating time") {
        val harness = atB(energy = 50, settings = LoopbackSettings(energyDrainPercentPerKm = 0.0))
        harness.send(charge)
        harness.clock.advanceTo(12_000)
        harness.states().last() shouldBe VehicleState.CHARGING
        harness.clock.advanceTo(17_000)
        harness.executedAt() shouldContainExactly listOf(17_000L)
        harness.energies().last() shouldBe 55
        harness.clock.runUntilIdle()
        harness.energies() shouldBe (50..100).toList()
        harness.context.timesOf<Report.Energy>().last() shouldBe 62_000L
        harness.states().last() shouldBe VehicleState.IDLE
    }

    test("charging stops when the next command starts moving") {
        val harness = atB(energy = 50, settings = LoopbackSettings(energyDrainPercentPerKm = 0.0))
        harness.send(charge)
        harness.clock.advanceTo(21_000)
        harness.energies().last() shouldBe 59
        harness.send(command("B--C", "C", "B", order = "T2"))
        harness.states().last() shouldBe VehicleState.EXECUTING
        harness.clock.runUntilIdle()
        harness.energies().last() shouldBe 59
    }

    test("charging goes on while the next command waits for a single step") {
        val harness = atB(energy = 50, settings = LoopbackSettings(energyDrainPercentPerKm = 0.0))
        harness.send(charge)
        harness.clock.advanceTo(17_000)
        harness.message(LoopbackMessages.SET_SINGLE_STEP_MODE_ENABLED, "value" to "true")
        harness.send(command("B--C", "C", "B", order = "T2"))
        harness.clock.advanceTo(31_000)
        harness.energies().last() shouldBe 69
        harness.states().last() shouldBe VehicleState.CHARGING
    }
})
