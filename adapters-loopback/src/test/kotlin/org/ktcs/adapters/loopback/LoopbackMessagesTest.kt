package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.adapters.loopback.LoopbackFixtures.aToB
import org.ktcs.adapters.loopback.LoopbackMessages.CURRENT_MOVEMENT_COMMAND_FAILED
import org.ktcs.adapters.loopback.LoopbackMessages.PUBLISH_EVENT
import org.ktcs.adapters.loopback.LoopbackMessages.RESET_POSITION
import org.ktcs.adapters.loopback.LoopbackMessages.RESET_PRECISE_POSITION
import org.ktcs.adapters.loopback.LoopbackMessages.RESET_PROPERTY
import org.ktcs.adapters.loopback.LoopbackMessages.SET_ENERGY_LEVEL
import org.ktcs.adapters.loopback.LoopbackMessages.SET_LOADED
import org.ktcs.adapters.loopback.LoopbackMessages.SET_ORIENTATION_ANGLE
import org.ktcs.adapters.loopback.LoopbackMessages.SET_POSITION
import org.ktcs.adapters.loopback.LoopbackMessages.SET_PRECISE_POSITION
import org.ktcs.adapters.loopback.LoopbackMessages.SET_PROPERTY
import org.ktcs.adapters.loopback.LoopbackMessages.SET_SINGLE_STEP_MODE_ENABLED
import org.ktcs.adapters.loopback.LoopbackMessages.SET_STATE
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.LoadHandlingDevice
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState

class LoopbackMessagesTest : FunSpec({
    /** Sends a message to a fresh vehicle and returns what it reported because of it. */
    fun reportsFor(type: String, vararg parameters: Pair<String, String>): List<Report> {
        val harness = Harness()
        val before = harness.context.reports.size
        harness.message(type, *parameters)
        return harness.context.reports.drop(before)
    }

    fun rejection(type: String, problem: String) =
        Report.Notification(NotificationLevel.NOTEWORTHY, "V: ignored message $type: $problem")

    test("setPosition moves the vehicle to a point") {
        reportsFor(SET_POSITION, "position" to "C") shouldContainExactly listOf(
            Report.PositionReport("C"),
            Report.PrecisePosition(Position(10_000, 10_000), Double.NaN),
        )
        reportsFor(LoopbackMessages.INIT_POSITION, "position" to "C").first() shouldBe Report.PositionReport("C")
    }

    test("setPosition rejects an unknown point or a missing parameter") {
        reportsFor(SET_POSITION, "position" to "X") shouldBe
            listOf(rejection(SET_POSITION, "there is no point named 'X'"))
        reportsFor(SET_POSITION) shouldBe listOf(rejection(SET_POSITION, "parameter 'position' is missing"))
    }

    test("resetPosition and resetPrecisePosition forget where the vehicle is") {
        reportsFor(RESET_POSITION) shouldBe listOf(Report.PositionReport(null))
        reportsFor(RESET_PRECISE_POSITION) shouldBe listOf(Report.PrecisePosition(null, Double.NaN))
    }

    test("setPrecisePosition takes x, y and an optional z") {
        reportsFor(SET_PRECISE_POSITION, "x" to "1", "y" to "-2", "z" to "3") shouldBe
            listOf(Report.PrecisePosition(Position(1, -2, 3), Double.NaN))
        reportsFor(SET_PRECISE_POSITION, "x" to "1", "y" to "2") shouldBe
            listOf(Report.PrecisePosition(Position(1, 2, 0), Double.NaN))
        reportsFor(SET_PRECISE_POSITION, "x" to "1.5", "y" to "2") shouldBe
            listOf(rejection(SET_PRECISE_POSITION, "parameter 'x' must be a whole number, was '1.5'"))
    }

    test("setOrientationAngle turns the vehicle") {
        reportsFor(SET_ORIENTATION_ANGLE, "angle" to "90") shouldBe
            listOf(Report.PrecisePosition(Position(0, 0), 90.0))
        reportsFor(SET_ORIENTATION_ANGLE, "orientationAngle" to "-45.5").single() shouldBe
            Report.PrecisePosition(Position(0, 0), -45.5)
        reportsFor(SET_ORIENTATION_ANGLE, "angle" to "north") shouldBe
            listOf(rejection(SET_ORIENTATION_ANGLE, "parameter 'angle' must be a number, was 'north'"))
    }

    test("setEnergyLevel sets the energy within 0 to 100") {
        reportsFor(SET_ENERGY_LEVEL, "value" to "40") shouldBe listOf(Report.Energy(40))
        reportsFor(SET_ENERGY_LEVEL, "energyLevel" to "0") shouldBe listOf(Report.Energy(0))
        reportsFor(SET_ENERGY_LEVEL, "value" to "full") shouldBe
            listOf(rejection(SET_ENERGY_LEVEL, "parameter 'value' must be a number, was 'full'"))
        reportsFor(SET_ENERGY_LEVEL, "value" to "150") shouldBe
            listOf(rejection(SET_ENERGY_LEVEL, "parameter 'value' must be 0 to 100, was 150.0"))
    }

    test("setLoaded fills or empties the load handling device") {
        // A change of the load is also published as a driver event; a message that changes nothing publishes none.
        reportsFor(SET_LOADED, "value" to "true") shouldBe listOf(
            Report.Devices(listOf(LoadHandlingDevice("default", true))),
            Report.Event(LoopbackEvents.LOAD_CHANGED, mapOf("loaded" to "true")),
        )
        reportsFor(SET_LOADED, "loaded" to "FALSE") shouldBe
            listOf(Report.Devices(listOf(LoadHandlingDevice("default", false))))
        reportsFor(SET_LOADED, "value" to "maybe") shouldBe
            listOf(rejection(SET_LOADED, "parameter 'value' must be true or false, was 'maybe'"))
    }

    test("setState reports a vehicle state by name") {
        reportsFor(SET_STATE, "value" to "ERROR") shouldBe listOf(Report.State(VehicleState.ERROR))
        reportsFor(SET_STATE, "state" to "charging") shouldBe listOf(Report.State(VehicleState.CHARGING))
        reportsFor(SET_STATE, "value" to "FLYING") shouldBe listOf(
            rejection(
                SET_STATE,
                "parameter 'value' must be one of UNKNOWN, UNAVAILABLE, ERROR, IDLE, EXECUTING, CHARGING, was 'FLYING'",
            ),
        )
    }

    test("setSingleStepModeEnabled needs a boolean") {
        reportsFor(SET_SINGLE_STEP_MODE_ENABLED, "value" to "yes") shouldBe
            listOf(rejection(SET_SINGLE_STEP_MODE_ENABLED, "parameter 'value' must be true or false, was 'yes'"))
    }

    test("currentMovementCommandFailed fails the command being carried out, where the vehicle is") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(1_000)
        harness.message(CURRENT_MOVEMENT_COMMAND_FAILED)
        harness.context.reportsOf<Report.Failed>() shouldBe listOf(Report.Failed(aToB))
        harness.states().last() shouldBe VehicleState.IDLE
        harness.clock.runUntilIdle()
        harness.executedAt() shouldBe emptyList()
        reportsFor(CURRENT_MOVEMENT_COMMAND_FAILED) shouldBe
            listOf(rejection(CURRENT_MOVEMENT_COMMAND_FAILED, "the vehicle has no command"))
    }

    test("setProperty and resetProperty change vehicle properties") {
        val harness = Harness()
        harness.message(SET_PROPERTY, "key" to "colour", "value" to "red")
        harness.context.vehicle().properties["colour"] shouldBe "red"
        harness.message(RESET_PROPERTY, "key" to "colour")
        harness.context.vehicle().properties.containsKey("colour") shouldBe false
        harness.message(SET_PROPERTY, "key" to " ", "value" to "red")
        harness.message(SET_PROPERTY, "key" to "colour")
        harness.notifications() shouldContainExactly listOf(
            "V: ignored message $SET_PROPERTY: parameter 'key' is blank",
            "V: ignored message $SET_PROPERTY: parameter 'value' is missing",
        )
    }

    test("publishEvent publishes its type with the other parameters as payload") {
        reportsFor(PUBLISH_EVENT, "type" to "bump", "force" to "3") shouldBe
            listOf(Report.Event("bump", mapOf("force" to "3")))
        reportsFor(PUBLISH_EVENT, "eventAppendix" to "x") shouldBe
            listOf(Report.Event(LoopbackMessages.DEFAULT_EVENT_TYPE, mapOf("eventAppendix" to "x")))
    }

    test("unknown message types are ignored") {
        reportsFor("tcs:virtualVehicle:fly", "to" to "moon") shouldBe emptyList()
        reportsFor("something:else") shouldBe emptyList()
    }
})
