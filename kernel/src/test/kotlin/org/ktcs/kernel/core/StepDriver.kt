package org.ktcs.kernel.core

import org.ktcs.api.driver.BasicVehicleDriver
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.VehicleState

/**
 * A test vehicle: drives a path in its length in milliseconds (1 m/s), operates for one second, and starts at the
 * point its `loopback:initialPosition` property names.
 */
open class StepDriver(name: String, context: DriverContext) : BasicVehicleDriver(name, context) {
    private var busyUntil = 0L

    override fun onEnabled() {
        context.vehicle().properties["loopback:initialPosition"]?.let(context::reportPosition)
        context.reportState(VehicleState.IDLE)
    }

    override fun sendCommand(command: MovementCommand) {
        val length = command.step.path?.let { context.plantModel.path(it)?.length } ?: 0L
        val operating = if (command.hasOperation) 1_000L else 0L
        val now = context.clock.elapsedMillis()
        busyUntil = maxOf(busyUntil, now) + length + operating
        context.reportState(VehicleState.EXECUTING)
        context.clock.schedule(busyUntil - now) {
            context.reportPosition(command.step.destinationPoint)
            onCommandExecuted(command)
            if (pendingCommands.isEmpty()) context.reportState(VehicleState.IDLE)
        }
    }
}

class StepDriverFactory : VehicleDriverFactory {
    override val name = "step"
    override val description = "test vehicle that drives at 1 m/s"

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver = StepDriver(vehicleName, context)
}
