package org.ktcs.kernel.vehicles

import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder
import org.ktcs.kernel.routing.lockedPathsBetween

// Rerouting a vehicle's current drive order: on request (the API, the deadlock watchdog) or to avoid a blocked start.

internal sealed interface RerouteOutcome

internal data object Rerouted : RerouteOutcome

internal data object NothingLeft : RerouteOutcome

internal data class Refused(val reason: String) : RerouteOutcome

/**
 * Routes the current drive order anew around [avoid]. A [safely] rerouted vehicle (to break a deadlock or avoid a
 * blocked start) keeps its route if the new one would make it wait, through others, for itself: the watchdog would
 * otherwise trade the cycle it breaks for one the new route closes, and back again at its next check.
 */
internal fun VehicleController.attemptReroute(
    avoid: Set<String>,
    forced: Boolean,
    onRequest: Boolean,
    safely: Boolean,
): RerouteOutcome {
    val order = currentOrder?.let(env.orders::require) ?: return Refused("vehicle $name has no transport order")
    if (withdrawing) return Refused("the order ${order.name} of vehicle $name is being withdrawn")
    val driveOrder = order.driveOrders[order.currentDriveOrderIndex]
    val oldRoute = driveOrder.route ?: return Refused("drive order ${driveOrder.name} has no route")
    val position = env.plant.vehicle(name).currentPosition
        ?: return Refused("the position of vehicle $name is unknown")
    val sentEnd = sent.lastOrNull()?.command?.step?.destinationPoint
    if (onRequest && !forced && sentEnd == null) {
        val expected = expectedPosition(order.currentRouteStepIndex, oldRoute) ?: position
        if (position != expected) {
            return Refused(
                "vehicle $name stands at $position, not at $expected where its route goes on; a forced " +
                    "reroute starts from where it stands",
            )
        }
    }
    val start = if (forced) position else sentEnd ?: position
    val target = oldRoute.finalDestinationPoint
        ?: return Refused("drive order ${driveOrder.name} has no destination")
    if (start == target && !forced) return NothingLeft
    val found = env.router().routes(env.plant.vehicle(name), start, target, avoid).firstOrNull()
        ?: return Refused("no route for vehicle $name from $start to $target" + lockedPathsText(start, target))
    if (safely && closesCycle(order, commandsAhead(order, reroutedDriveOrder(order, driveOrder, oldRoute, found)))) {
        return Refused("the new route of vehicle $name would close a cycle of waiting vehicles")
    }
    // A forced reroute forgets the commands sent: the new route then keeps only the steps driven.
    if (forced) restartFrom(start)
    followNewRoute(order, reroutedDriveOrder(order, driveOrder, oldRoute, found))
    return Rerouted
}

/** Whether claiming [ahead] and the drive orders after the current one would make the vehicle wait for itself. */
private fun VehicleController.closesCycle(order: TransportOrder, ahead: List<PlannedCommand>): Boolean =
    env.scheduler().claimWouldBeBlocked(this, restOfOrder(order, order.currentDriveOrderIndex, ahead))

private fun VehicleController.plannedCommands(order: TransportOrder, driveOrder: DriveOrder): List<PlannedCommand> =
    plannedCommands(order, driveOrder, driveOrder.route!!) { env.plant.staticModel().location(it)?.name }

/** How many steps of the current drive order's route the vehicle drove or was sent: a new route keeps them. */
private fun VehicleController.keptSteps(order: TransportOrder): Int = order.currentRouteStepIndex + 1 + sent.size

/** The commands of the (rerouted) current drive order [driveOrder] still ahead of the vehicle. */
private fun VehicleController.commandsAhead(order: TransportOrder, driveOrder: DriveOrder): List<PlannedCommand> =
    plannedCommands(order, driveOrder).drop(keptSteps(order))

/** Where the route expects the vehicle once it carried out every command sent: after step [stepIndex]. */
private fun expectedPosition(stepIndex: Int, route: Route): String? =
    route.steps.getOrNull(stepIndex)?.destinationPoint
        ?: route.steps.firstOrNull()?.let { it.sourcePoint ?: it.destinationPoint }

/** [driveOrder] with the steps already driven or sent of [oldRoute], then [found]. */
private fun VehicleController.reroutedDriveOrder(
    order: TransportOrder,
    driveOrder: DriveOrder,
    oldRoute: Route,
    found: Route,
): DriveOrder {
    val kept = oldRoute.steps.take(keptSteps(order))
    val route =
        Route(kept + found.steps.mapIndexed { i, step -> step.copy(routeIndex = kept.size + i) }, found.costs)
    return driveOrder.copy(route = route)
}

private fun VehicleController.followNewRoute(order: TransportOrder, rerouted: DriveOrder) {
    env.orders.update(order.name) { current ->
        current.copy(driveOrders = current.driveOrders.map { if (it.name == rerouted.name) rerouted else it })
    }
    if (waiting != null) {
        env.scheduler().clearPendingAllocations(this)
        waiting = null
    }
    remaining.clear()
    remaining.addAll(commandsAhead(order, rerouted))
    claimRestOfOrder(order, order.currentDriveOrderIndex)
    publishResources()
    requestNext()
}

/** Forgets the commands sent to the driver and holds only [position], where a forced reroute starts. */
private fun VehicleController.restartFrom(position: String) {
    driver?.clearCommandQueue()
    sent.clear()
    val heldPosition = position in held.all()
    env.scheduler().free(this, held.releaseAllBut(setOf(position)))
    if (!heldPosition) env.scheduler().allocateNow(this, setOf(position))
}

private fun VehicleController.lockedPathsText(start: String, target: String): String {
    val locked = env.plant.layoutWithLocks().lockedPathsBetween(start, target)
    return if (locked.isEmpty()) "" else ": locked path ${locked.joinToString()} blocks the way"
}

/**
 * Routes the drive orders after the current one that pass [avoid] anew around it, if the plant allows, and claims the
 * new way; returns whether one of them changed. A deadlock may lie past the current drive order: a vehicle held back
 * before a station because of the way it would leave it by.
 */
internal fun VehicleController.rerouteLaterLegs(avoid: Set<String>): Boolean {
    val order = currentOrder?.let(env.orders::require) ?: return false
    if (withdrawing) return false
    val later = order.driveOrders.drop(order.currentDriveOrderIndex + 1).filter { leg ->
        leg.route?.steps.orEmpty().any { it.path in avoid || it.destinationPoint in avoid }
    }
    return rerouteLegs(order, later, avoid)
}

/**
 * Routes each of [legs] (drive orders of [order] not started yet) around [avoid] where possible and claims the result,
 * unless that would make the vehicle wait, through others, for itself.
 */
internal fun VehicleController.rerouteLegs(order: TransportOrder, legs: List<DriveOrder>, avoid: Set<String>): Boolean {
    val found = legs.mapNotNull { leg ->
        val route = leg.route ?: return@mapNotNull null
        val start = route.steps.firstOrNull()?.sourcePoint ?: return@mapNotNull null
        val target = route.finalDestinationPoint ?: return@mapNotNull null
        env.router().routes(env.plant.vehicle(name), start, target, avoid).firstOrNull()
            ?.takeIf { it.steps != route.steps }
            ?.let { leg.name to it }
    }.toMap()
    if (found.isEmpty()) return false
    fun TransportOrder.withNewRoutes() =
        copy(driveOrders = driveOrders.map { leg -> found[leg.name]?.let { leg.copy(route = it) } ?: leg })
    if (closesCycle(order.withNewRoutes(), listOfNotNull(waiting) + remaining)) return false
    env.orders.update(order.name) { it.withNewRoutes() }
    claimRestOfOrder(env.orders.require(order.name), order.currentDriveOrderIndex)
    return true
}

/**
 * Routes the rest of the current drive order through the free park point [park] and on to where it went (a
 * *retreat*: off the lanes, the vehicle frees its point for the vehicles held back behind it), the way to [park]
 * avoiding [occupied]; taken only if the vehicle would not wait, through others, for itself with it. Returns whether
 * the vehicle follows the new route.
 */
internal fun VehicleController.retreatVia(park: String, occupied: Set<String>): Boolean {
    val order = currentOrder?.let(env.orders::require) ?: return false
    // Sent its last step, the vehicle is bound to arrive and operate: a detour after that step would be driven after
    // the drive order ended, as steps of the next one.
    if (withdrawing || sent.lastOrNull()?.command?.finalMovement == true) return false
    val driveOrder = order.driveOrders[order.currentDriveOrderIndex]
    val oldRoute = driveOrder.route ?: return false
    val vehicle = env.plant.vehicle(name)
    val start = sent.lastOrNull()?.command?.step?.destinationPoint ?: vehicle.currentPosition ?: return false
    val target = oldRoute.finalDestinationPoint ?: return false
    val away = env.router().routes(vehicle, start, park, occupied - start).firstOrNull() ?: return false
    val back = env.router().routes(vehicle, park, target).firstOrNull() ?: return false
    val steps = (away.steps + back.steps).filter { it.path != null }
    if (steps.isEmpty()) return false
    val rerouted = reroutedDriveOrder(order, driveOrder, oldRoute, Route(steps, away.costs + back.costs))
    val ahead = commandsAhead(order, rerouted)
    // Nothing ahead (a stale step index once made it so: a detour appended after a last step already sent, now
    // refused above) would leave the vehicle with nothing to ask for, standing where it is for good.
    if (ahead.isEmpty() || closesCycle(order, ahead)) return false
    followNewRoute(order, rerouted)
    return true
}
