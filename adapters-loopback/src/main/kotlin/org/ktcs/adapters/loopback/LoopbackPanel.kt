package org.ktcs.adapters.loopback

import org.ktcs.adapters.loopback.LoopbackMessages.CURRENT_MOVEMENT_COMMAND_FAILED
import org.ktcs.adapters.loopback.LoopbackMessages.PUBLISH_EVENT
import org.ktcs.adapters.loopback.LoopbackMessages.RESET_POSITION
import org.ktcs.adapters.loopback.LoopbackMessages.SET_ENERGY_LEVEL
import org.ktcs.adapters.loopback.LoopbackMessages.SET_LOADED
import org.ktcs.adapters.loopback.LoopbackMessages.SET_ORIENTATION_ANGLE
import org.ktcs.adapters.loopback.LoopbackMessages.SET_POSITION
import org.ktcs.adapters.loopback.LoopbackMessages.SET_SINGLE_STEP_MODE_ENABLED
import org.ktcs.adapters.loopback.LoopbackMessages.SET_STATE
import org.ktcs.adapters.loopback.LoopbackMessages.SET_TIME_FACTOR
import org.ktcs.adapters.loopback.LoopbackMessages.TRIGGER_SINGLE_STEP
import org.ktcs.api.driver.DriverCommand
import org.ktcs.api.driver.DriverPanel
import org.ktcs.api.driver.DriverParameter
import org.ktcs.api.driver.ParameterType
import org.ktcs.api.model.VehicleState

/**
 * The loopback vehicle's panel in the overview (openTCS's loopback comm adapter panel): position, orientation,
 * energy, state, load, single-step mode, time factor, failing the current command and publishing an event. The
 * kernel checks every command against these declarations before [LoopbackMessageHandler] carries it out.
 */
internal object LoopbackPanel {
    private const val DIRECTORY = "org/ktcs/adapters/loopback/panel"
    private val STATES = VehicleState.entries.map { it.name }

    val panel: DriverPanel = DriverPanel(
        title = "Loopback (simulated vehicle)",
        resourceDirectory = DIRECTORY,
        classLoader = LoopbackPanel::class.java.classLoader,
        commands = listOf(
            DriverCommand(
                SET_POSITION,
                "Puts the vehicle on a point (facing as the point says)",
                listOf(DriverParameter("position", ParameterType.POINT, "the point")),
            ),
            DriverCommand(RESET_POSITION, "Makes the vehicle's position unknown"),
            DriverCommand(
                SET_ORIENTATION_ANGLE,
                "Turns the vehicle",
                listOf(DriverParameter("angle", ParameterType.NUMBER, "degrees", min = -360.0, max = 360.0)),
            ),
            // snippet:driver-panel-commands
            DriverCommand(
                SET_ENERGY_LEVEL,
                "Sets the battery level",
                listOf(DriverParameter("value", ParameterType.INTEGER, "percent", min = 0.0, max = 100.0)),
            ),
            DriverCommand(
                SET_STATE,
                "Sets the vehicle's state, e.g. ERROR or UNAVAILABLE to keep it from taking orders",
                listOf(DriverParameter("value", ParameterType.CHOICE, "the state", values = STATES)),
            ),
            // end-snippet
            DriverCommand(
                SET_LOADED,
                "Says whether the vehicle carries a load",
                listOf(DriverParameter("value", ParameterType.BOOLEAN, "carries a load")),
            ),
            DriverCommand(
                SET_SINGLE_STEP_MODE_ENABLED,
                "In single-step mode the vehicle waits for a step before each command",
                listOf(DriverParameter("value", ParameterType.BOOLEAN, "single-step mode on")),
            ),
            DriverCommand(TRIGGER_SINGLE_STEP, "In single-step mode: carries out the next command"),
            DriverCommand(
                SET_TIME_FACTOR,
                "How many times faster than real time this vehicle moves and operates",
                listOf(DriverParameter("value", ParameterType.NUMBER, "time factor", min = 0.01, max = 1000.0)),
            ),
            DriverCommand(
                CURRENT_MOVEMENT_COMMAND_FAILED,
                "Reports the current command failed (its order is withdrawn)",
            ),
            DriverCommand(
                PUBLISH_EVENT,
                "Publishes a driver event, as a real vehicle would",
                listOf(
                    DriverParameter("type", ParameterType.TEXT, "the event type", required = false),
                    DriverParameter("text", ParameterType.TEXT, "what happened", required = false),
                ),
            ),
        ),
    )
}
