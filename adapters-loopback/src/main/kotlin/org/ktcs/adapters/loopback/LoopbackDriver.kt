package org.ktcs.adapters.loopback

import org.ktcs.api.driver.BasicVehicleDriver
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Explained
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrder

/**
 * A simulated vehicle (openTCS's "loopback" adapter). It drives each command's path with a trapezoidal velocity
 * profile on the kernel clock, one scheduled event per path rather than a tick every 100 ms, performs operations,
 * uses energy while driving and recharges at the recharge operation.
 *
 * - Enabling places it at its remembered position, else at the point named by [LoopbackProperties.INITIAL_POSITION],
 *   else at the position the kernel knows, else (with [LoopbackSettings.placeUnpositionedVehicles]) on a free park
 *   position or point chosen by [Placement], telling the operator; it takes energy, load and pause state from the
 *   kernel's view of the vehicle.
 * - Disabling stops it where it is and reports state UNKNOWN: the driver no longer knows what the vehicle does. The
 *   position stays reported because the vehicle still occupies it.
 * - Pausing freezes driving and operations; charging goes on.
 *
 * Confined to the kernel context, like every driver.
 */
class LoopbackDriver(
    vehicleName: String,
    context: DriverContext,
    settings: LoopbackSettings = LoopbackSettings(),
    private val placement: Placement? = Placement().takeIf { settings.placeUnpositionedVehicles },
) : BasicVehicleDriver(vehicleName, context, settings.commandQueueCapacity, settings.rechargeOperation) {
    private val vehicle = VirtualVehicle(context)
    private val simulation = Simulation(context, settings, vehicle, Queue())
    private val messages = LoopbackMessageHandler(context, vehicle, simulation)

    /** Whether the vehicle waits for [LoopbackMessages.TRIGGER_SINGLE_STEP] before each command. */
    val isSingleStepModeEnabled: Boolean get() = simulation.singleStepMode

    override fun sendCommand(command: MovementCommand) = simulation.commandAdded()

    override fun onEnabled() {
        val known = context.vehicle()
        simulation.reset()
        placeAtStart(known)
        vehicle.battery.reset(known.energyLevel.toDouble())
        vehicle.setLoaded(known.loadHandlingDevices.any { it.full })
        vehicle.changeState(VehicleState.IDLE)
        simulation.pause(known.paused)
    }

    override fun onDisabled() {
        simulation.reset()
        vehicle.changeState(VehicleState.UNKNOWN)
    }

    override fun onCommandQueueCleared() = simulation.commandsDropped()

    /** Vetoes orders that load a loaded vehicle or unload an empty one, counting from the current load state. */
    override fun canProcess(order: TransportOrder): Explained {
        val operations = order.driveOrders.drop(order.currentDriveOrderIndex.coerceAtLeast(0))
            .map { it.destination.operation }
        return LoadConflicts.check(operations, vehicle.loaded, simulation.parameters())
    }

    override fun processMessage(message: DriverMessage) = messages.handle(message)

    override fun onPaused(paused: Boolean) = simulation.pause(paused)

    // snippet:driver-panel-state
    override fun panelState(): Map<String, String> = mapOf(
        "singleStepMode" to simulation.singleStepMode.toString(),
        "waitingForStep" to simulation.isWaitingForStep().toString(),
        "timeFactor" to simulation.timeFactor.toString(),
        "simulationPaused" to simulation.isPaused.toString(),
        "loaded" to vehicle.loaded.toString(),
    )
    // end-snippet

    private fun placeAtStart(known: Vehicle) {
        // A restarted kernel knows where the vehicle was last (the state store): it resumes there, not at its start.
        val name = vehicle.position ?: known.currentPosition ?: known.properties[LoopbackProperties.INITIAL_POSITION]
            ?: return placeUnpositioned(known)
        val point = context.plantModel.point(name)
        if (point == null) {
            val text = "${known.name}: no point named '$name' to start at; position stays unknown"
            return context.notifyUser(NotificationLevel.NOTEWORTHY, text)
        }
        vehicle.reportPoint(point.name)
        vehicle.place(point.pose.position, point.pose.orientationAngle)
    }

    private fun placeUnpositioned(known: Vehicle) {
        placement ?: return
        val point = placement.startPoint(known, context)
            ?: return context.notifyUser(NotificationLevel.NOTEWORTHY, "${known.name}: no free point to place it on")
        vehicle.reportPoint(point.name)
        vehicle.place(point.pose.position, point.pose.orientationAngle)
        context.notifyUser(NotificationLevel.NOTEWORTHY, placement.announce(known, point))
    }

    private inner class Queue : CommandQueue {
        override val pending: List<MovementCommand> get() = pendingCommands

        override fun executed(command: MovementCommand) = onCommandExecuted(command)

        override fun failed(command: MovementCommand) = onCommandFailed(command)
    }
}
