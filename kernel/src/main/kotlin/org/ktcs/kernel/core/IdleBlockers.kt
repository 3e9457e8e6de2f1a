package org.ktcs.kernel.core

import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.Point
import org.ktcs.api.model.PointType
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.Destination
import org.ktcs.api.order.Operations
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.dispatching.PARK_ORDER_TYPE
import org.ktcs.kernel.dispatching.VehicleAvailability
import org.ktcs.kernel.routing.pointsLinkedToLocations
import org.ktcs.kernel.scheduling.WaitForGraph
import org.slf4j.LoggerFactory

/**
 * Moves idle vehicles out of the way of vehicles that wait for what they stand on. An idle vehicle on another's route
 * (parked on a through lane, or left at the station where it finished) waits for nothing, so no deadlock check finds
 * it, yet the vehicle behind it would wait forever (openTCS leaves this to the operator). A vehicle that has stood in
 * someone's way for two checks in a row is sent to the nearest free park position, else to the nearest free point,
 * away from every route and allocation.
 *
 * The work is in proportion to the waiting vehicles; the plant is searched only when a vehicle must be moved.
 */
class IdleBlockers(private val kernel: KernelCore, private val state: KernelState) {
    private val log = LoggerFactory.getLogger(IdleBlockers::class.java)
    private var blockingBefore = emptySet<String>()
    private val ordersSent = HashMap<String, String>()
    private val availability = VehicleAvailability(state.orders::get, state.sequences::get)

    /** How many vehicles were sent out of the way so far. */
    var moved = 0
        private set

    fun check(graph: WaitForGraph) {
        val waiting = graph.edges.keys
        val blocking = graph.edges.values.flatMapTo(HashSet()) { it.keys }.filter { it !in waiting && isIdle(it) }
        blocking.filter { it in blockingBefore && !hasOrderUnderWay(it) }.forEach { vehicle ->
            val waiters = waiting.filter { graph.edges.getValue(it).containsKey(vehicle) }
            moveAway(state.plant.vehicle(vehicle), waiters)
        }
        blockingBefore = blocking.toSet()
    }

    private fun isIdle(name: String): Boolean {
        val vehicle = state.plant.vehicleOrNull(name) ?: return false
        return vehicle.orderSequence == null && availability.isAvailable(vehicle, PARKING)
    }

    // An order sent earlier that the vehicle has not taken yet (e.g. it is still charging) is not sent twice.
    private fun hasOrderUnderWay(vehicle: String): Boolean =
        ordersSent[vehicle]?.let { state.orders.get(it)?.state?.isFinal == false } == true

    private fun moveAway(vehicle: Vehicle, waiters: List<String>) {
        val refuge = refugeFor(vehicle) ?: return log.warn(
            "vehicle {} blocks {} but has no free point to move to",
            vehicle.name,
            waiters,
        )
        val operation = if (refuge.type == PointType.PARK_POSITION) Operations.PARK else Operations.MOVE
        val order = kernel.createTransportOrder(
            TransportOrderCreation(
                name = "Clear-",
                destinations = listOf(Destination(refuge.name, operation)),
                incompleteName = true,
                type = PARK_ORDER_TYPE,
                intendedVehicle = vehicle.name,
                dispensable = true,
            ),
        )
        ordersSent[vehicle.name] = order.name
        moved++
        val text = "vehicle ${vehicle.name} stood idle in the way of ${waiters.joinToString()} at " +
            "${vehicle.currentPosition}; sent to ${refuge.name} with order ${order.name}"
        state.notifications.publish("deadlock watchdog", NotificationLevel.NOTEWORTHY, text)
        log.info(text)
        kernel.dispatch()
    }

    // Park positions first, then points no location is linked to, then the rest; the nearest of the best kind.
    private fun refugeFor(vehicle: Vehicle): Point? {
        val taken = HashSet<String>()
        state.plant.vehicles().forEach { other ->
            other.currentPosition?.let(taken::add)
            other.allocatedResources.forEach(taken::addAll)
            other.claimedResources.forEach(taken::addAll)
        }
        val model = state.plant.layoutWithLocks()
        val linked = model.pointsLinkedToLocations()
        val costs = kernel.router.costsFrom(vehicle, vehicle.currentPosition!!)
        return model.points.asSequence()
            .filter { it.name !in taken }
            .mapNotNull { point -> costs(point.name)?.let { point to it } }
            .minWithOrNull(
                compareBy<Pair<Point, Long>>(
                    { (point, _) -> kindRank(point, linked) },
                    { (_, cost) -> cost },
                ),
            )?.first
    }

    private companion object {
        val PARKING = VehicleAvailability.Work(orderType = PARK_ORDER_TYPE, mayReplaceDispensable = false)
    }

    private fun kindRank(point: Point, linked: Set<String>): Int = when {
        point.type == PointType.PARK_POSITION -> 0
        point.name !in linked -> 1
        else -> 2
    }
}
