package org.ktcs.kernel.vehicles

/**
 * A vehicle starting a route from where it stood may find its first step leading into a queue of vehicles that
 * wait for its own point (it stood idle beside a full loop, or at a station whose other way out it was counted
 * on to take): going that way would close a deadlock. Route around that step's path instead (a detour that leaves
 * the point free, even if it joins the same queue later), else around the whole step, if the plant allows. Where
 * what blocks it lies beyond its first move (a vehicle coming the other way on a two-way aisle), route around that
 * first. Returns whether the current drive order was rerouted (and its first step asked for).
 */
internal fun VehicleController.avoidBlockedStart(): Boolean {
    val scheduler = env.scheduler()
    if (sent.isNotEmpty() || !scheduler.claimIsBlocked(this)) return false
    val position = env.plant.vehicle(name).currentPosition
    val first = remaining.firstOrNull() ?: return false
    // On a two-way aisle the vehicles it would meet head-on may stand far beyond its first step: route around them.
    // A new route for a later drive order only changes the claim: the vehicle still starts this one as planned.
    val blockers = scheduler.claimBlockers(this) - held.all()
    val beyondFirstStep = blockers.isNotEmpty() && blockers.none(firstMove()::contains)
    val onCurrent = remaining.any { command -> command.resources.any(blockers::contains) }
    if (beyondFirstStep && reroute(blockers) && !scheduler.claimIsBlocked(this)) return onCurrent
    val path = first.command.step.path
    if (remaining.all { it.command.step.path == null }) {
        rerouteNextLeg()
        claimBlocked = scheduler.claimIsBlocked(this)
        return false
    }
    if (path != null && reroute(setOf(path)) && !scheduler.claimIsBlocked(this)) return true
    val rerouted = reroute(first.resources - setOfNotNull(position))
    claimBlocked = scheduler.claimIsBlocked(this)
    return rerouted
}

/**
 * The current drive order is an operation where the vehicle stands, so its first move, the one that would close
 * the cycle, is the next drive order's: route that drive order around its first path, if the plant allows, and
 * claim the new way. Its commands are planned when it starts.
 */
private fun VehicleController.rerouteNextLeg() {
    val order = env.orders.require(currentOrder!!)
    val next = order.driveOrders.getOrNull(order.currentDriveOrderIndex + 1) ?: return
    val first = next.route?.steps?.firstOrNull()?.path ?: return
    rerouteLegs(order, listOf(next), setOf(first))
}

/** What the vehicle's first move takes: the first step with a path of this drive order, else of the next one. */
private fun VehicleController.firstMove(): Set<String> {
    remaining.firstOrNull { it.command.step.path != null }?.let { return it.resources }
    val order = env.orders.require(currentOrder!!)
    val step = order.driveOrders.getOrNull(order.currentDriveOrderIndex + 1)?.route?.steps?.firstOrNull()
    return setOfNotNull(step?.path, step?.destinationPoint)
}
