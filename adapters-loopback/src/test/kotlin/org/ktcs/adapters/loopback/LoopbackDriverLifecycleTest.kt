package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.adapters.loopback.LoopbackFixtures.aToB
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState

class LoopbackDriverLifecycleTest : FunSpec({
    test("enabling reports the initial position, IDLE, the energy and the empty load handling device") {
        val harness = Harness(vehicle = LoopbackFixtures.vehicle(energy = 80))
        harness.context.reports shouldContainExactly listOf(
            Report.PositionReport("A"),
            Report.PrecisePosition(Position(0, 0), Double.NaN),
            Report.Energy(80),
            Report.Devices(listOf(LoadHandlingDevice("default", false))),
            Report.State(VehicleState.IDLE),
        )
        harness.driver.isEnabled shouldBe true
    }

    test("without an initial position, and placing switched off, the position stays unknown") {
        val vehicle = LoopbackFixtures.vehicle().let { it.copy(properties = emptyMap()) }
        val harness = Harness(LoopbackSettings(placeUnpositionedVehicles = false), vehicle = vehicle)
        harness.context.reportsOf<Report.PositionReport>() shouldBe emptyList()
        harness.notifications() shouldBe emptyList()
    }

    test("an initial position that names no point is reported to the operators and ignored") {
        val harness = Harness(vehicle = LoopbackFixtures.vehicle(LoopbackProperties.INITIAL_POSITION to "Nowhere"))
        harness.context.reportsOf<Report.PositionReport>() shouldBe emptyList()
        harness.notifications().single() shouldContain "Nowhere"
    }

    test("a vehicle that was loaded stays loaded") {
        val loaded = LoopbackFixtures.vehicle().copy(loadHandlingDevices = listOf(LoadHandlingDevice("fork", true)))
        val harness = Harness(vehicle = loaded)
        harness.context.reportsOf<Report.Devices>().last().devices shouldBe listOf(LoadHandlingDevice("default", true))
    }

    test("disabling stops the vehicle where it is, drops its commands and reports UNKNOWN") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(6_000)
        harness.driver.disable()
        harness.states().last() shouldBe VehicleState.UNKNOWN
        harness.context.reportsOf<Report.PrecisePosition>().last().position shouldBe Position(5_000, 0)
        harness.driver.pendingCommands shouldBe emptyList()
        harness.clock.runUntilIdle()
        harness.executedAt() shouldBe emptyList()
    }

    test("enabled again, the vehicle is where it last reported") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.runUntilIdle()
        harness.driver.disable()
        harness.driver.enable()
        harness.context.reportsOf<Report.PositionReport>().last() shouldBe Report.PositionReport("B")
        harness.states().last() shouldBe VehicleState.IDLE
    }

    test("clearing the command queue stops the vehicle where it is, IDLE") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(1_000)
        harness.driver.clearCommandQueue()
        harness.states().last() shouldBe VehicleState.IDLE
        harness.context.reportsOf<Report.PrecisePosition>().last().position shouldBe Position(250, 0)
        harness.clock.runUntilIdle()
        harness.executedAt() shouldBe emptyList()
        harness.context.reportsOf<Report.PositionReport>().last() shouldBe Report.PositionReport("A")
    }

    test("the factory creates loopback drivers with the configured queue and recharge operation") {
        val factory = LoopbackDriverFactory(LoopbackSettings(commandQueueCapacity = 3, rechargeOperation = "Charge"))
        val context = FakeDriverContext(LoopbackFixtures.plant(), LoopbackFixtures.VEHICLE)
        val driver = factory.create(LoopbackFixtures.VEHICLE, context)
        factory.name shouldBe "loopback"
        driver.commandQueueCapacity shouldBe 3
        driver.rechargeOperation shouldBe "Charge"
        driver.isEnabled shouldBe false
        context.reports shouldBe emptyList()
    }
})
