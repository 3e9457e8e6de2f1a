package org.ktcs.kernel.dispatching

import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.RecoveryEvaluator
import org.ktcs.api.error.KernelException
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.slf4j.Logger
import org.slf4j.LoggerFactory
import java.time.Instant

/**
 * What one dispatch run sees and has done so far. Vehicles are read at the start, the dispatchable orders when a phase
 * first needs them (a run in which no vehicle is available never reads them, so creating an order while every
 * vehicle is busy costs no scan of the waiting orders); what the run assigns itself is tracked here, so later phases
 * do not depend on when the kernel updates its snapshots.
 */
internal class DispatchRun(
    val context: DispatchContext,
    val configuration: DispatcherConfiguration,
    val recovery: RecoveryEvaluator,
) {
    val now: Instant = context.clock.now()
    val model: PlantModel = context.plantModel()
    val vehicles: List<Vehicle> = context.vehicles().toList()
    val dispatchableOrders: List<TransportOrder> by lazy {
        ordersRead = true
        context.dispatchableOrders().toList()
    }

    /** Whether the kernel refused an assignment in this run (the next run must try again). */
    var kernelRefused: Boolean = false
        private set

    /** Whether this run has read the dispatchable orders. */
    var ordersRead: Boolean = false
        private set
    val routes = RouteCache(context.router)
    val priorities = Priorities(configuration, now)

    private val orders = HashMap<String, TransportOrder?>()
    private val sequences = HashMap<String, OrderSequence?>()
    private val assignedVehicles = HashSet<String>()
    private val assignedOrders = HashSet<String>()
    private val claimed = HashSet<String>()

    /** Points and locations that orders assigned in this run go to. */
    val claimedTargets: Set<String> get() = claimed

    fun order(name: String): TransportOrder? = orders.getOrPut(name) { context.transportOrder(name) }

    fun sequence(name: String): OrderSequence? = sequences.getOrPut(name) { context.orderSequence(name) }

    fun isAssigned(vehicle: Vehicle): Boolean = vehicle.name in assignedVehicles

    fun isAssigned(order: TransportOrder): Boolean = order.name in assignedOrders

    /** Gives the candidate's order to its vehicle; `false` if the kernel refused. */
    fun assign(candidate: Candidate): Boolean {
        // One assignment the kernel refuses must not keep every other vehicle waiting until the next run.
        try {
            context.assign(candidate.order.name, candidate.vehicle.name, candidate.driveOrders)
        } catch (e: KernelException) {
            log.warn("Could not assign {}: {}", candidate, e.message)
            kernelRefused = true
            return false
        }
        assignedVehicles += candidate.vehicle.name
        assignedOrders += candidate.order.name
        claimed += finalTargets(candidate.order, candidate.driveOrders)
        return true
    }

    /** Milliseconds since [vehicle]'s procState last changed. */
    fun idleMillis(vehicle: Vehicle): Long = now.toEpochMilli() - vehicle.procStateTimestamp.toEpochMilli()

    private companion object {
        val log: Logger = LoggerFactory.getLogger(DefaultDispatcher::class.java)
    }
}

/** Where an order ends: its last destination and, once routed, the point its last route ends at. */
internal fun finalTargets(order: TransportOrder, driveOrders: List<DriveOrder> = order.driveOrders): Set<String> {
    val last = driveOrders.lastOrNull() ?: order.driveOrders.lastOrNull() ?: return emptySet()
    return setOfNotNull(last.destination.target, last.route?.finalDestinationPoint)
}
