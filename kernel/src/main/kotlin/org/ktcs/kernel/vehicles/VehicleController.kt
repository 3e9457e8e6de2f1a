package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.CommandStage
import org.ktcs.api.driver.MovementCommand
import org.ktcs.api.driver.QueuedCommand
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.scheduling.SchedulerClient
import org.ktcs.kernel.orders.HistoryCodes
import org.slf4j.LoggerFactory

/**
 * Carries one vehicle through its transport order: claims the route, asks the scheduler for the resources of one
 * movement command at a time, sends each granted command to the driver, gives back what lies behind the vehicle,
 * and moves on drive order by drive order until the order is finished or withdrawn. Confined to the kernel context.
 */
class VehicleController(override val name: String, internal val env: VehicleEnvironment) : SchedulerClient {
    private val log = LoggerFactory.getLogger(VehicleController::class.java)

    // Internal, not private: the rerouting in Rerouting.kt and BlockedStart.kt works on the same state.
    internal val held = HeldResources()
    internal val remaining = ArrayDeque<PlannedCommand>()
    internal val sent = ArrayDeque<PlannedCommand>()
    internal var waiting: PlannedCommand? = null

    /**
     * Whether the vehicle's fresh claim waits, through others, for itself and no route around it was found: some
     * vehicle in its way has to yield first ([org.ktcs.kernel.core.BlockedClaims]). Cleared at its next grant.
     */
    var claimBlocked = false
        internal set

    // The vehicle's `transportOrder` is the one store of the order it works on; the controller reads it there.
    internal val currentOrder: String? get() = env.plant.vehicle(name).transportOrder
    internal var withdrawing = false
        private set
    private var withdrawReason = ""

    var driver: VehicleDriver? = null
        private set
    var driverName: String? = null
        private set

    /** The name of the order this controller is working on, if any. */
    val transportOrder: String? get() = currentOrder

    fun attach(driverName: String, driver: VehicleDriver) {
        check(currentOrder == null) {
            "vehicle '$name' is processing order '$currentOrder'; withdraw it before changing the driver"
        }
        this.driver?.disable()
        this.driver = driver
        this.driverName = driverName
    }

    /**
     * Whether the vehicle is carrying out a command it was sent (driving or operating) and not paused: it makes
     * progress and will report, so a wait of its is no deadlock yet.
     */
    internal val isMoving: Boolean get() = sent.isNotEmpty() && !env.plant.vehicle(name).paused

    /** How many commands the driver has reported carried out, ever: a count that moves while the vehicle does. */
    internal var commandsDone = 0L
        private set

    /** The commands of the current drive order: sent to the driver, waiting for resources, then the rest. */
    fun commandQueue(): List<QueuedCommand> =
        sent.map { QueuedCommand(it.command, CommandStage.SENT) } +
            listOfNotNull(waiting).map { QueuedCommand(it.command, CommandStage.WAITING_FOR_RESOURCES) } +
            remaining.map { QueuedCommand(it.command, CommandStage.QUEUED) }

    /** Starts [order], which is BEING_PROCESSED by this vehicle with a route for every drive order. */
    fun assign(order: TransportOrder) = resume(order, 0)

    /**
     * Works on [order] from its drive order [index] on (0 for a new order; a later one when a restarted kernel
     * continues an order), with a route from where the vehicle is for every drive order from [index].
     */
    fun resume(order: TransportOrder, index: Int) {
        check(currentOrder == null) { "vehicle '$name' is already processing '$currentOrder'" }
        withdrawing = false
        env.plant.updateVehicle(name) {
            it.copy(
                transportOrder = order.name,
                orderSequence = order.wrappingSequence ?: it.orderSequence,
            ).withProcState(ProcState.PROCESSING_ORDER, env)
        }
        startDriveOrder(index)
    }

    private fun startDriveOrder(index: Int) {
        val order = env.orders.require(currentOrder!!)
        val driveOrder = order.driveOrders[index]
        val route = checkNotNull(driveOrder.route) { "drive order ${driveOrder.name} of '${order.name}' has no route" }
        env.orders.update(order.name) { current ->
            current.copy(
                currentDriveOrderIndex = index,
                currentRouteStepIndex = -1,
                driveOrders = current.driveOrders.mapIndexed { i, it ->
                    if (i == index) {
                        it.copy(state = DriveOrderState.TRAVELLING)
                    } else {
                        it
                    }
                },
            )
        }
        remaining.clear()
        remaining.addAll(plannedCommands(order, driveOrder, route) { env.plant.staticModel().location(it)?.name })
        claimRestOfOrder(order, index)
        if (avoidBlockedStart()) return
        publishResources()
        requestNext()
    }

    /**
     * Claims what is left of the current drive order and the routes of the drive orders after it: deadlock
     * avoidance judges the whole way the vehicle still has to go, so that it never starts a leg it cannot finish.
     */
    internal fun claimRestOfOrder(order: TransportOrder, index: Int) {
        // A step asked for and not granted yet is still ahead: rerouting the later drive orders while the vehicle
        // waits for a grant must not drop it from the claim.
        env.scheduler().claim(this, restOfOrder(order, index, listOfNotNull(waiting) + remaining))
    }

    /** The claim for [order] from its drive order [index] on: [ahead] (what is left of that one), then the later ones. */
    internal fun restOfOrder(order: TransportOrder, index: Int, ahead: List<PlannedCommand>): List<Set<String>> {
        val later = order.driveOrders.drop(index + 1).flatMap { driveOrder ->
            val route = driveOrder.route ?: return@flatMap emptyList()
            plannedCommands(order, driveOrder, route) { env.plant.staticModel().location(it)?.name }
        }
        return (ahead + later).map { it.resources }
    }

    internal fun requestNext() {
        val driver = driver ?: return
        if (withdrawing || waiting != null || !driver.isEnabled) return
        if (sent.size >= driver.commandQueueCapacity) return
        // Asked for before the vehicle reached the end of the path, the way back would be granted while it still holds
        // the point it left, and a retreat through a bay would free nothing.
        if (sent.isNotEmpty() && (remaining.firstOrNull() ?: return).turnsBackFrom(sent.last())) return
        val next = remaining.removeFirstOrNull() ?: return
        waiting = next
        env.scheduler().allocate(this, next.resources)
    }

    override fun onAllocationGranted(resources: Set<String>): Boolean {
        val granted = waiting?.takeIf { it.resources == resources } ?: return false
        waiting = null
        if (driver?.enqueueCommand(granted.command) != true) {
            remaining.addFirst(granted)
            return false
        }
        held.add(resources)
        claimBlocked = false
        sent.addLast(granted)
        publishResources()
        requestNext()
        return true
    }

    override fun heldAfter(resources: Set<String>): Set<String> =
        held.keptAfter(resources, ::pathLength, lengthToCover())

    override fun heldAfter(steps: List<Set<String>>): Set<String> = held.keptAfter(steps, ::pathLength, lengthToCover())

    fun onCommandExecuted(command: MovementCommand) {
        val done = sent.firstOrNull()
        if (done?.command != command) {
            log.warn("vehicle={} reported an unexpected command executed: {}", name, command.step)
            return
        }
        sent.removeFirst()
        commandsDone++
        env.scheduler().free(
            this,
            held.passed(done.resources, command.step.destinationPoint, ::pathLength, lengthToCover()),
        )
        env.orders.update(command.transportOrder) { it.copy(currentRouteStepIndex = command.step.routeIndex) }
        publishResources()
        when {
            withdrawing -> if (sent.isEmpty()) endOrder(TransportOrderState.FAILED)
            command.finalMovement -> finishDriveOrder()
            else -> requestNext()
        }
    }

    /** The driver reports that the vehicle failed [command], for [reason] if it gave one: the order is withdrawn. */
    fun onCommandFailed(command: MovementCommand, reason: String = "") {
        val step = command.step.path ?: command.step.destinationPoint
        val why = if (reason.isBlank()) "" else ": $reason"
        env.notifications.publish(
            name,
            NotificationLevel.IMPORTANT,
            "vehicle $name failed to carry out $step of order ${command.transportOrder}$why; the order is withdrawn",
        )
        withdraw(immediate = true, reason = if (reason.isBlank()) "withdrawn" else "vehicle $name failed $step$why")
    }

    private fun finishDriveOrder() {
        val order = env.orders.require(currentOrder!!)
        val index = order.currentDriveOrderIndex
        env.orders.update(order.name) { current ->
            current.copy(
                driveOrders = current.driveOrders.mapIndexed { i, it ->
                    if (i == index) {
                        it.copy(state = DriveOrderState.FINISHED)
                    } else {
                        it
                    }
                },
                history =
                current.history +
                    HistoryEntry(
                        env.context.now(),
                        HistoryCodes.ORDER_FINISHED_DRIVE_ORDER,
                        current.driveOrders[index].name,
                    ),
            )
        }
        if (index + 1 < order.driveOrders.size) startDriveOrder(index + 1) else endOrder(TransportOrderState.FINISHED)
    }

    /**
     * Withdraws the current order: at once ([immediate]), or after the commands already sent are carried out.
     * [reason] goes into the order's history, so operators see why it ended.
     */
    fun withdraw(immediate: Boolean, reason: String = "withdrawn") {
        val order = currentOrder ?: return
        if (env.orders.require(order).state == TransportOrderState.BEING_PROCESSED) {
            env.orders.transition(order, TransportOrderState.WITHDRAWN, reason)
        }
        withdrawReason = reason
        withdrawing = true
        remaining.clear()
        if (waiting != null) {
            env.scheduler().clearPendingAllocations(this)
            waiting = null
        }
        if (immediate) {
            driver?.clearCommandQueue()
            sent.clear()
        }
        env.scheduler().claim(this, sent.map { it.resources })
        if (sent.isEmpty()) endOrder(TransportOrderState.FAILED)
    }

    private fun endOrder(state: TransportOrderState) {
        val order = currentOrder!!
        withdrawing = false
        claimBlocked = false
        remaining.clear()
        env.scheduler().unclaim(this)
        releaseAllButPosition()
        // The vehicle is free before the order's final state is published: an order reserved for it may be
        // assigned right then.
        env.plant.updateVehicle(name) { it.copy(transportOrder = null).withProcState(ProcState.IDLE, env) }
        env.orders.transition(order, state, if (state == TransportOrderState.FAILED) withdrawReason else "")
        withdrawReason = ""
        if (state != TransportOrderState.FINISHED) warnIfStillLoaded(order)
        env.vehicleMayBeAvailable()
    }

    /** An order that ends between its load and unload leaves a load that makes the driver refuse later orders. */
    private fun warnIfStillLoaded(order: String) {
        if (env.plant.vehicle(name).loadHandlingDevices.none { it.full }) return
        env.notifications.publish(
            name,
            NotificationLevel.NOTEWORTHY,
            "vehicle $name still carries a load after its order $order ended unfinished; its driver may refuse " +
                "orders that load it until the load is removed (for a simulated vehicle: reset the load in its " +
                "panel, or send it the driver message tcs:virtualVehicle:setLoaded with value=false)",
        )
    }

    /** The vehicle reported its position; outside an order that is where it holds resources. */
    fun onPositionReported(point: String?) {
        val before = env.plant.vehicle(name).currentPosition
        val vehicle = env.plant.updateVehicle(name) { it.copy(currentPosition = point) }
        if (currentOrder == null) occupyPosition(vehicle.integrationLevel) else checkOnRoute(point)
        // A vehicle placed (or moved by hand) may be the one a waiting order needs.
        if (currentOrder == null && point != before) env.vehicleMayBeAvailable()
    }

    /** A vehicle with an order reports only points of the commands it was sent; anything else is worth a look. */
    private fun checkOnRoute(point: String?) {
        if (!env.reportPositionOffRoute || point == null) return
        val expected = sent.flatMap { listOfNotNull(it.command.step.sourcePoint, it.command.step.destinationPoint) }
        if (expected.isEmpty() || point in expected) return
        env.notifications.publish(
            name,
            NotificationLevel.IMPORTANT,
            "vehicle $name reports position $point, which is not on its route (expected one of " +
                "${expected.distinct().joinToString()})",
        )
    }

    /**
     * Holds exactly the vehicle's current point, as its integration level asks. If another vehicle holds that point
     * (the vehicle was placed or reported there while ignored), it is not allocated twice: the vehicle drops to
     * TO_BE_NOTICED, with a notification, until its position is free.
     */
    fun occupyPosition(level: IntegrationLevel) {
        val point = env.plant.vehicle(name).currentPosition
        val holders = positionHolders()
        val effective = if (holders.isNotEmpty() && level >= IntegrationLevel.TO_BE_RESPECTED) {
            env.notifications.publish(name, NotificationLevel.IMPORTANT, positionTakenText(holders, level))
            env.plant.updateVehicle(name) { it.copy(integrationLevel = IntegrationLevel.TO_BE_NOTICED) }
            IntegrationLevel.TO_BE_NOTICED
        } else {
            level
        }
        val wanted = if (point != null && effective >= IntegrationLevel.TO_BE_RESPECTED) setOf(point) else emptySet()
        if (held.asList() == listOfNotNull(wanted.takeIf { it.isNotEmpty() })) return
        env.scheduler().free(this, held.releaseAllBut(emptySet()))
        if (wanted.isNotEmpty()) {
            env.scheduler().allocateNow(this, wanted)
            held.reset(wanted)
        }
        publishResources()
    }

    /** The other vehicles that hold the point this vehicle stands on. */
    fun positionHolders(): Set<String> {
        val point = env.plant.vehicle(name).currentPosition ?: return emptySet()
        return env.scheduler().allocations().filter { (client, resources) -> client != name && point in resources }.keys
    }

    fun positionTakenText(holders: Set<String>, level: IntegrationLevel): String =
        "vehicle $name stays below TO_BE_RESPECTED instead of $level: its position " +
            "${env.plant.vehicle(name).currentPosition} is held by ${holders.sorted().joinToString()}; " +
            "raise it again once the position is free"

    private fun pathLength(resources: Set<String>): Long = resources.sumOf {
        env.plant.staticModel().path(it)?.length
            ?: 0L
    }

    private fun lengthToCover(): Long = when (env.resourceManagement) {
        ResourceManagement.LENGTH_RESPECTED -> env.plant.vehicle(name).boundingBox.length
        ResourceManagement.LENGTH_IGNORED -> 0
    }

    private fun releaseAllButPosition() {
        val position = env.plant.vehicle(name).currentPosition
        env.scheduler().free(this, held.releaseAllBut(setOfNotNull(position)))
        publishResources()
    }

    internal fun publishResources() {
        env.plant.updateVehicle(name) {
            it.copy(
                allocatedResources = held.asList(),
                claimedResources = (listOfNotNull(waiting) + remaining).map { c ->
                    c.resources
                },
            )
        }
    }

    /**
     * Routes the rest of the current drive order anew around [avoid], from where the vehicle will be after the commands
     * it was already sent, or, if the current drive order does not pass [avoid], the later ones that do; returns whether
     * it now follows a new route. Used to break deadlocks: a new route that would make the vehicle wait, through
     * others, for itself (close another cycle) is not taken.
     */
    fun reroute(avoid: Set<String>): Boolean =
        if (avoid.isEmpty() || (listOfNotNull(waiting) + remaining).any { it.resources.any(avoid::contains) }) {
            attemptReroute(avoid, forced = false, onRequest = false, safely = true) == Rerouted
        } else {
            // What to avoid lies past the current drive order: routing that one anew would change nothing.
            rerouteLaterLegs(avoid)
        }

    /**
     * Routes the rest of the current drive order anew around [avoid], as openTCS's rerouting does: a regular reroute
     * starts where the vehicle will be after the commands it was already sent (and is refused for a vehicle that
     * stands off its route); a [forced] one starts from the vehicle's current position, also off its route: the
     * driver's queue is cleared and everything but the position is given back, so use it only on a vehicle that
     * stands still. Returns why it could not reroute, or null if the vehicle follows a new route (or has nothing
     * left to reroute).
     */
    fun reroute(avoid: Set<String>, forced: Boolean): String? =
        (attemptReroute(avoid, forced, onRequest = true, safely = false) as? Refused)?.reason

    /** Sends the vehicle on through the free park point [park] (see [retreatVia]); returns whether it was. */
    fun retreat(park: String, occupied: Set<String>): Boolean = retreatVia(park, occupied)

    /** The driver can take more commands now (e.g. it was enabled). */
    fun onDriverReady() {
        requestNext()
    }
}
