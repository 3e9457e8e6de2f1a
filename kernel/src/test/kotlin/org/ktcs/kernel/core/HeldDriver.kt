package org.ktcs.kernel.core

import org.ktcs.api.driver.BasicVehicleDriver
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.model.VehicleState

/** A vehicle that carries out a command only when the test says it has arrived. */
internal class HeldDriver(name: String, context: DriverContext) : BasicVehicleDriver(name, context) {
    private val underWay = ArrayDeque<MovementCommand>()

    /** The commands sent and not carried out yet, oldest first. */
    val sentCommands: List<MovementCommand> get() = underWay.toList()

    override fun onEnabled() {
        context.vehicle().properties["loopback:initialPosition"]?.let(context::reportPosition)
        context.reportState(VehicleState.IDLE)
    }

    override fun sendCommand(command: MovementCommand) {
        underWay += command
        context.reportState(VehicleState.EXECUTING)
    }

    fun arrive() {
        val command = underWay.removeFirst()
        context.reportPosition(command.step.destinationPoint)
        onCommandExecuted(command)
        if (underWay.isEmpty()) context.reportState(VehicleState.IDLE)
    }
}

/** A module of [HeldDriver]s, each put into [drivers] by its vehicle's name as it is made. */
internal fun heldDrivers(drivers: MutableMap<String, HeldDriver>) =
    driverModule("held", "test vehicle that arrives when the test says so") { vehicleName, context ->
        HeldDriver(vehicleName, context).also { drivers[vehicleName] = it }
    }
