package org.ktcs.adapters.loopback

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.maps.shouldContain
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import org.ktcs.adapters.loopback.LoopbackFixtures.aToB
import org.ktcs.adapters.loopback.LoopbackFixtures.bToC

class LoopbackPanelTest : FunSpec({
    fun Harness.events() = context.reportsOf<Report.Event>()

    test("every command the panel declares is one the vehicle carries out, and its files are on the class path") {
        val harness = Harness()
        val handled = LoopbackMessageHandler(
            harness.context,
            VirtualVehicle(harness.context),
            simulationOf(harness),
        ).types
        handled shouldContainAll LoopbackPanel.panel.commands.map { it.name }
        val panel = LoopbackDriverFactory().panel
        panel.classLoader.getResource("${panel.resourceDirectory}/${panel.entryModule}") shouldNotBe null
    }

    test("a faster time factor speeds up what the vehicle is doing, from the moment it is set") {
        val harness = Harness()
        harness.send(aToB)
        harness.clock.advanceTo(6_000)
        harness.message(LoopbackMessages.SET_TIME_FACTOR, "value" to "2")
        harness.clock.runUntilIdle()
        // 6 s of the 12 s drive were left; at twice the speed they take 3 s.
        harness.executedAt() shouldContainExactly listOf(9_000L)
        harness.driver.panelState() shouldContain ("timeFactor" to "2.0")
        harness.message(LoopbackMessages.SET_TIME_FACTOR, "value" to "0")
        harness.notifications().last() shouldBe "V: ignored message ${LoopbackMessages.SET_TIME_FACTOR}: " +
            "parameter 'value' must be above 0, was 0.0"
    }

    test("the vehicle publishes command and load events; single-step state shows in the panel state") {
        val harness = Harness()
        harness.message(LoopbackMessages.SET_SINGLE_STEP_MODE_ENABLED, "value" to "true")
        harness.send(aToB, bToC)
        harness.driver.panelState() shouldContain ("waitingForStep" to "true")
        harness.message(LoopbackMessages.TRIGGER_SINGLE_STEP)
        harness.driver.panelState() shouldContain ("waitingForStep" to "false")
        harness.clock.runUntilIdle()
        harness.message(LoopbackMessages.SET_LOADED, "value" to "true")
        harness.events().map { it.type } shouldContainExactly listOf(
            LoopbackEvents.SINGLE_STEP_MODE_CHANGED,
            LoopbackEvents.COMMAND_STARTED,
            LoopbackEvents.COMMAND_FINISHED,
            LoopbackEvents.LOAD_CHANGED,
        )
        harness.events()[1].payload shouldBe mapOf("order" to aToB.transportOrder, "point" to "B", "path" to "A--B")
        harness.events().last().payload shouldBe mapOf("loaded" to "true")
    }
})

private fun simulationOf(harness: Harness) = Simulation(
    harness.context,
    LoopbackSettings(),
    VirtualVehicle(harness.context),
    object : CommandQueue {
        override val pending = emptyList<org.ktcs.api.driver.MovementCommand>()

        override fun executed(command: org.ktcs.api.driver.MovementCommand) = Unit

        override fun failed(command: org.ktcs.api.driver.MovementCommand) = Unit
    },
)
