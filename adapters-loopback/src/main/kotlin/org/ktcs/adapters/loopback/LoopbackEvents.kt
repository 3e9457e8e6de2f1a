package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand

/**
 * The driver events a loopback vehicle publishes (the web API's WebSocket topic `driverEvents` and the SSE stream
 * carry them; the loopback panel shows the latest). Every command event's payload has `order`, `point` and, where
 * the step has them, `path` and `operation`.
 */
object LoopbackEvents {
    private const val PREFIX = "loopback:"

    /** The vehicle started driving a command's step. */
    const val COMMAND_STARTED: String = PREFIX + "commandStarted"

    /** The vehicle finished a command (drove the step and performed its operation). */
    const val COMMAND_FINISHED: String = PREFIX + "commandFinished"

    /** The vehicle could not carry out a command; payload `reason` says why. */
    const val COMMAND_FAILED: String = PREFIX + "commandFailed"

    /** The vehicle's load changed; payload `loaded` is `true` or `false`. */
    const val LOAD_CHANGED: String = PREFIX + "loadChanged"

    /** The simulation's time factor changed; payload `timeFactor`. */
    const val TIME_FACTOR_CHANGED: String = PREFIX + "timeFactorChanged"

    /** Single-step mode was switched; payload `enabled`. */
    const val SINGLE_STEP_MODE_CHANGED: String = PREFIX + "singleStepModeChanged"

    internal fun command(
        context: DriverContext,
        type: String,
        command: MovementCommand,
        extra: Map<String, String> = emptyMap(),
    ) {
        val payload = buildMap {
            put("order", command.transportOrder)
            put("point", command.step.destinationPoint)
            command.step.path?.let { put("path", it) }
            if (command.hasOperation) put("operation", command.operation)
            putAll(extra)
        }
        context.publishEvent(type, payload)
    }
}
