package org.ktcs.adapters.loopback

import org.ktcs.adapters.loopback.LoopbackMessages.CURRENT_MOVEMENT_COMMAND_FAILED
import org.ktcs.adapters.loopback.LoopbackMessages.DEFAULT_EVENT_TYPE
import org.ktcs.adapters.loopback.LoopbackMessages.INIT_POSITION
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
import org.ktcs.adapters.loopback.LoopbackMessages.SET_TIME_FACTOR
import org.ktcs.adapters.loopback.LoopbackMessages.TRIGGER_SINGLE_STEP
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.Position
import org.ktcs.api.model.VehicleState
import org.slf4j.LoggerFactory

/**
 * Carries out [LoopbackMessages]. A message with bad parameters changes nothing and tells the operators why; no
 * exception reaches the kernel.
 */
internal class LoopbackMessageHandler(
    private val context: DriverContext,
    private val vehicle: VirtualVehicle,
    private val simulation: Simulation,
) {
    private val handlers: Map<String, (MessageParameters) -> Unit> = mapOf(
        SET_POSITION to ::setPosition,
        INIT_POSITION to ::setPosition,
        RESET_POSITION to { vehicle.reportPoint(null) },
        SET_PRECISE_POSITION to { p -> vehicle.place(Position(p.long("x"), p.long("y"), zOf(p))) },
        RESET_PRECISE_POSITION to { vehicle.place(null) },
        SET_ORIENTATION_ANGLE to { p -> vehicle.turn(p.double("angle", "orientationAngle")) },
        SET_ENERGY_LEVEL to { p -> simulation.setEnergy(p.percent("value", "energyLevel")) },
        SET_LOADED to { p -> vehicle.setLoaded(p.boolean("value", "loaded")) },
        SET_STATE to { p -> vehicle.changeState(p.oneOf(VehicleState.entries.toTypedArray(), "value", "state")) },
        SET_SINGLE_STEP_MODE_ENABLED to { p -> simulation.setSingleStepMode(p.boolean("value", "enabled")) },
        TRIGGER_SINGLE_STEP to { simulation.triggerSingleStep() },
        SET_TIME_FACTOR to { p -> simulation.setTimeFactor(p.positive("value", "timeFactor")) },
        CURRENT_MOVEMENT_COMMAND_FAILED to { failCurrentCommand() },
        SET_PROPERTY to { p -> context.setVehicleProperty(key(p), p.string("value")) },
        RESET_PROPERTY to { p -> context.setVehicleProperty(key(p), null) },
        PUBLISH_EVENT to { p -> context.publishEvent(p.optional("type") ?: DEFAULT_EVENT_TYPE, p.all - "type") },
    )

    /** The message types this handler carries out. */
    val types: Set<String> get() = handlers.keys

    fun handle(message: DriverMessage) {
        val handler = handlers[message.type] ?: return log.debug("ignoring unknown message type {}", message.type)
        try {
            handler(MessageParameters(message.parameters))
        } catch (problem: MessageRejectedException) {
            reject(message, problem.message)
        } catch (problem: RuntimeException) {
            log.error("{} failed", message.type, problem)
            reject(message, problem.message ?: problem.javaClass.simpleName)
        }
    }

    private fun setPosition(parameters: MessageParameters) {
        val name = parameters.string("position")
        val point = context.plantModel.point(name) ?: throw MessageRejectedException("there is no point named '$name'")
        vehicle.reportPoint(point.name)
        vehicle.place(point.pose.position, point.pose.orientationAngle)
    }

    private fun failCurrentCommand() {
        if (!simulation.failCurrentCommand()) throw MessageRejectedException("the vehicle has no command")
    }

    private fun zOf(parameters: MessageParameters) = if (parameters.optional("z") == null) 0 else parameters.long("z")

    private fun key(parameters: MessageParameters) =
        parameters.string("key").ifBlank { throw MessageRejectedException("parameter 'key' is blank") }

    private fun reject(message: DriverMessage, problem: String?) = context.notifyUser(
        NotificationLevel.NOTEWORTHY,
        "${context.vehicle().name}: ignored message ${message.type}: $problem",
    )

    private companion object {
        val log = LoggerFactory.getLogger(LoopbackMessageHandler::class.java)
    }
}
