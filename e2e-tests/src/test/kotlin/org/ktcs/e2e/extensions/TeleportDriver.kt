package org.ktcs.e2e.extensions

import org.ktcs.api.driver.BasicVehicleDriver
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.model.VehicleState

/** A custom driver that needs only the api module: its vehicle arrives 100 ms after each command. */
class TeleportDriver(name: String, context: DriverContext) : BasicVehicleDriver(name, context) {
    override fun onEnabled() {
        context.vehicle().properties["loopback:initialPosition"]?.let(context::reportPosition)
        context.reportState(VehicleState.IDLE)
    }

    override fun sendCommand(command: MovementCommand) {
        context.clock.schedule(100) {
            context.reportPosition(command.step.destinationPoint)
            onCommandExecuted(command)
        }
    }
}

/** Found through META-INF/services/org.ktcs.api.driver.VehicleDriverFactory. */
class TeleportDriverFactory : VehicleDriverFactory {
    override val name = "teleport"
    override val description = "test vehicles that arrive 100 ms after each command"

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver = TeleportDriver(
        vehicleName,
        context,
    )
}
