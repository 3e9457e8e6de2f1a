package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder

/** A movement command and the resources the vehicle needs to carry it out. */
data class PlannedCommand(val command: MovementCommand, val resources: Set<String>)

/** The commands for one drive order, one per step of its route; the last one carries the operation. */
fun plannedCommands(
    order: TransportOrder,
    driveOrder: DriveOrder,
    route: Route,
    locationOf: (String) -> String?,
): List<PlannedCommand> {
    val destination = driveOrder.destination
    val location = locationOf(destination.target)
    val finalPoint = route.finalDestinationPoint ?: destination.target
    val properties = order.properties + destination.properties
    return route.steps.mapIndexed { index, step ->
        val last = index == route.steps.lastIndex
        val command = MovementCommand(
            transportOrder = order.name,
            driveOrder = driveOrder.name,
            step = step,
            operation = if (last) destination.operation else MovementCommand.NO_OPERATION,
            opLocation = if (last) location else null,
            finalMovement = last,
            finalDestination = finalPoint,
            finalDestinationLocation = location,
            finalOperation = destination.operation,
            properties = properties,
        )
        PlannedCommand(command, setOfNotNull(step.path, step.destinationPoint, command.opLocation))
    }
}

/** Whether this command drives back over the path of [last] (into a dead-end bay and out again). */
internal fun PlannedCommand.turnsBackFrom(last: PlannedCommand): Boolean {
    val path = command.step.path ?: return false
    return path == last.command.step.path
}
