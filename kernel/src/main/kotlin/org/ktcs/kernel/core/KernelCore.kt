package org.ktcs.kernel.core

import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.dispatching.RecoveryEvaluator
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.event.OrderSequenceEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.VehicleState
import org.ktcs.api.model.XmlSafeText
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.routing.Router
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.kernel.context.KernelContext
import org.ktcs.kernel.events.EventBus
import org.ktcs.kernel.events.Notifications
import org.ktcs.kernel.orders.HistoryCodes
import org.ktcs.kernel.orders.OrderLifecycle
import org.ktcs.kernel.orders.OrderSequencePool
import org.ktcs.kernel.orders.TransportOrderFactory
import org.ktcs.kernel.orders.TransportOrderPool
import org.ktcs.kernel.store.CommitBarrier
import org.ktcs.kernel.validation.InvalidModelException
import org.ktcs.kernel.validation.PlantModelValidator
import org.ktcs.kernel.vehicles.VehicleControllers
import org.ktcs.kernel.vehicles.VehicleEnvironment
import org.ktcs.kernel.workingset.ObjectNames
import org.ktcs.kernel.workingset.PlantState
import org.ktcs.kernel.workingset.TopologyChange

/**
 * The kernel's state and the operations on it, wired together: plant, orders, sequences, vehicle controllers and
 * the strategies. Everything here runs in [context]; the services in `kernel.services` are the way in from outside.
 */
class KernelCore(
    val context: KernelContext,
    model: PlantModel,
    val router: Router,
    val scheduler: Scheduler,
    private val dispatcherProvider: () -> Dispatcher,
    private val recoveryEvaluator: RecoveryEvaluator,
    driverFactories: List<VehicleDriverFactory>,
    val options: KernelOptions = KernelOptions(),
) {
    val events = EventBus(context)
    val notifications = Notifications(events, context)
    val plant = PlantState(model, events)
    val orders = TransportOrderPool(events, context)
    val sequences = OrderSequencePool(events, context)
    val names = ObjectNames(context)
    private val factory = TransportOrderFactory(context, names)
    val lifecycle = OrderLifecycle(orders, sequences, { router }, options.dismissUnroutableOrders)
    private val trigger = DispatchTrigger(
        context,
        dispatcherProvider,
        options.redispatchIntervalMillis,
        options.newOrderDispatchDelayMillis,
    )
    val dispatchContext = KernelDispatchContext(this)

    /** Where requests wait for their changes to be committed to the state store (none without a store). */
    var commits: CommitBarrier = CommitBarrier.NONE
    val controllers = VehicleControllers(
        VehicleEnvironment(context, events, plant, orders, notifications, {
            scheduler
        }, { router }, trigger::request, options.resourceManagement, options.watchdog.reportPositionOffRoute),
        driverFactories,
    )

    /** The dispatcher in use (the default one, or one an extension put in its place). */
    val dispatcher: Dispatcher get() = dispatcherProvider()

    // The DISPATCHABLE orders, oldest first; kept up to date from order events (track), changed nowhere else.
    private val dispatchable = LinkedHashMap<String, TransportOrder>()
    private var sweep: Cancellable? = null
    val watchdog = DeadlockWatchdog(this)

    /** What an operator or host may ask directly (assign now, intended vehicle, thresholds, locks), with its rules. */
    val requests = OperatorRequests(this)
    private val operationsWatchdog = OperationsWatchdog(this)

    init {
        events.listen(lifecycle::onEvent)
        events.listen(::track)
    }

    /** Starts the strategies, the vehicles and the periodic tasks; call in the kernel context. */
    fun start() {
        router.initialize()
        router.updateTopology(plant.layoutWithLocks())
        scheduler.initialize()
        recoveryEvaluator.initialize()
        dispatcherProvider().initialize()
        controllers.start(options.enableDriversOnStart, options.initialIntegrationLevel)
        announceTrafficLimits()
        trigger.start()
        watchdog.start()
        operationsWatchdog.start()
        scheduleSweep()
        trigger.request()
    }

    fun stop() {
        sweep?.cancel()
        watchdog.stop()
        operationsWatchdog.stop()
        trigger.stop()
        controllers.stop()
        dispatcherProvider().terminate()
        recoveryEvaluator.terminate()
        scheduler.terminate()
        router.terminate()
    }

    fun dispatch() = trigger.request()

    /** The DISPATCHABLE orders, oldest first (a read-only view). */
    fun dispatchableOrders(): Collection<TransportOrder> = dispatchable.values

    /** Puts back a DISPATCHABLE order read from the state store at start (no event: nothing changed). */
    fun restoreDispatchable(order: TransportOrder) {
        dispatchable[order.name] = order
    }

    fun nameTaken(name: String): Boolean =
        orders.contains(name) || sequences.get(name) != null || plant.staticModel().objectNamed(name) != null

    fun createTransportOrder(creation: TransportOrderCreation): TransportOrder {
        val order = factory.create(creation, plant.layoutWithLocks(), ::nameTaken, orders::contains, sequences::get)
        orders.add(order)
        return orders.require(order.name)
    }

    fun createOrderSequence(creation: OrderSequenceCreation): OrderSequence {
        XmlSafeText.require(creation.name, "the order sequence name '${XmlSafeText.printable(creation.name)}'")
        XmlSafeText.require(creation.type, "order sequence '${XmlSafeText.printable(creation.name)}': the type")
        XmlSafeText.requireProperties(creation.properties, "order sequence '${XmlSafeText.printable(creation.name)}'")
        val name = if (creation.incompleteName) names.complete(creation.name) else creation.name
        if (nameTaken(name)) throw ObjectExistsException("an object named '$name' exists already")
        creation.intendedVehicle?.let { plant.vehicle(it) }
        return sequences.add(
            OrderSequence(
                name = name,
                creationTime = context.now(),
                type = creation.type,
                orderTypes = creation.orderTypes,
                intendedVehicle = creation.intendedVehicle,
                failureFatal = creation.failureFatal,
                properties = creation.properties,
            ),
        )
    }

    fun markSequenceComplete(name: String) {
        sequences.update(name) {
            if (it.complete) {
                it
            } else {
                it.copy(
                    complete = true,
                    history = it.history + HistoryEntry(context.now(), HistoryCodes.SEQUENCE_COMPLETED),
                )
            }
        }
        lifecycle.onSequenceCompleted(name, context.now())
    }

    /** Gives the DISPATCHABLE [order] to the idle [vehicle] with routed [driveOrders]. */
    fun assign(order: String, vehicle: String, driveOrders: List<DriveOrder>) {
        val current = orders.require(order)
        if (current.state != TransportOrderState.DISPATCHABLE) {
            throw IllegalStateChangeException("transport order '$order' is ${current.state}, not DISPATCHABLE")
        }
        orders.update(order) {
            it.copy(
                processingVehicle = vehicle,
                driveOrders = driveOrders,
                history = it.history + HistoryEntry(context.now(), HistoryCodes.ORDER_ASSIGNED, vehicle),
            )
        }
        orders.transition(order, TransportOrderState.BEING_PROCESSED)
        current.wrappingSequence?.let { sequence ->
            sequences.update(sequence) { it.copy(processingVehicle = vehicle) }
        }
        controllers.controller(vehicle).assign(orders.require(order))
    }

    /** Withdraws [order]: an unassigned one fails at once, an assigned one through its vehicle. */
    fun withdraw(order: String, immediate: Boolean, disableVehicle: Boolean) {
        val current = orders.require(order)
        if (current.state.isFinal) {
            throw IllegalStateChangeException(
                "transport order '$order' is ${current.state} already",
            )
        }
        val vehicle = current.processingVehicle
        if (vehicle == null ||
            current.state !in setOf(TransportOrderState.BEING_PROCESSED, TransportOrderState.WITHDRAWN)
        ) {
            if (current.state != TransportOrderState.WITHDRAWN) orders.transition(order, TransportOrderState.WITHDRAWN)
            orders.transition(order, TransportOrderState.FAILED, "withdrawn")
            return
        }
        if (disableVehicle) controllers.setIntegrationLevel(vehicle, IntegrationLevel.TO_BE_RESPECTED)
        controllers.controller(vehicle).withdraw(immediate)
    }

    /**
     * Locks or unlocks a path and updates the routing topology; vehicles whose remaining route uses a path that
     * was just locked are routed around it where possible (otherwise they keep their route, as openTCS's
     * IGNORE_PATH_LOCKS strategy does, and the lock applies to new routes).
     */
    fun setPathLocked(path: String, locked: Boolean) {
        plant.setPathLocked(path, locked)
        router.updateTopology(plant.layoutWithLocks())
        if (locked) rerouteAround(path)
        trigger.request()
    }

    private fun rerouteAround(path: String) {
        plant.vehicles().filter { vehicle -> vehicle.claimedResources.any { path in it } }.forEach { vehicle ->
            if (!controllers.controller(vehicle.name).reroute(emptySet())) {
                notifications.publish(
                    vehicle.name,
                    NotificationLevel.NOTEWORTHY,
                    "vehicle ${vehicle.name} has no way around locked path $path and keeps its route",
                )
            }
        }
    }

    /**
     * Replaces the plant with [model] when nothing is under way: no transport order that is not final, no order
     * sequence that is not finished, no vehicle moving. Drops final orders and finished sequences, then starts the
     * new vehicles. A model that differs only in path locks, path velocities and location locks is applied at
     * once, also while vehicles drive: vehicles keep running and those whose route uses a newly locked path are
     * routed around it. [persist] runs once the model is accepted and before it applies; if it throws, the plant
     * stays as it was.
     */
    fun replacePlantModel(model: PlantModel, persist: (PlantModel) -> Unit = {}) {
        val topologyChange = TopologyChange.between(plant.model(), model)
        if (topologyChange == null) refuseWhileBusy()
        try {
            PlantModelValidator.requireValid(model)
        } catch (error: InvalidModelException) {
            throw InvalidRequestException(error.message!!.lines().joinToString(" ") { it.trim() })
        }
        persist(model)
        if (topologyChange != null) return applyTopologyChange(topologyChange)
        controllers.discard()
        orders.removeFinal()
        sequences.removeFinished()
        dispatchable.clear()
        plant.replace(model)
        router.updateTopology(plant.layoutWithLocks())
        scheduler.updatePlantModel(plant.layoutWithLocks())
        controllers.start(options.enableDriversOnStart, options.initialIntegrationLevel)
        announceTrafficLimits()
        trigger.request()
    }

    private fun applyTopologyChange(change: TopologyChange) {
        val running = plant.model()
        plant.apply(change)
        router.updateTopology(plant.layoutWithLocks())
        change.paths.filter { it.locked && running.path(it.name)?.locked == false }.forEach { rerouteAround(it.name) }
        trigger.request()
    }

    // Where the plant itself defeats deadlock avoidance (dead ends with several stops), operators hear it at once.
    private fun announceTrafficLimits() {
        PlantModelValidator.trafficWarnings(plant.layoutWithLocks()).forEach {
            notifications.publish("traffic control", NotificationLevel.IMPORTANT, "${it.element}: ${it.message}")
        }
    }

    private fun refuseWhileBusy() {
        val busyOrders = orders.all().filterNot { it.state.isFinal }.map { it.name }
        val openSequences = sequences.all().filterNot { it.finished }.map { it.name }
        // An order withdrawn immediately is final at once, while its vehicle may still be finishing a movement.
        val moving = plant.vehicles().filter { it.state == VehicleState.EXECUTING }.map { it.name }
        if (busyOrders.isEmpty() && openSequences.isEmpty() && moving.isEmpty()) return
        val reasons = listOfNotNull(
            busyOrders.takeIf { it.isNotEmpty() }?.let { "${it.size} transport order(s) not final (${it.sample()})" },
            openSequences.takeIf {
                it.isNotEmpty()
            }?.let { "${it.size} order sequence(s) not finished (${it.sample()})" },
            moving.takeIf { it.isNotEmpty() }?.let { "${it.size} vehicle(s) still moving (${it.sample()})" },
        )
        throw IllegalStateChangeException(
            "the plant model cannot be replaced while orders are being processed: ${reasons.joinToString("; ")}; " +
                "withdraw them or wait until they are done",
        )
    }

    private fun List<String>.sample(): String = take(SAMPLE_SIZE).joinToString() + if (size > SAMPLE_SIZE) ", …" else ""

    private fun track(event: KernelEvent) {
        when (event) {
            is TransportOrderEvent -> trackOrder(event)
            is OrderSequenceEvent -> releaseFinishedSequence(event)
            else -> Unit
        }
    }

    private fun trackOrder(event: TransportOrderEvent) {
        val order = event.current
        if (order == null || order.state != TransportOrderState.DISPATCHABLE) {
            (order ?: event.previous)?.let { dispatchable.remove(it.name) }
            if (order != null && order.state.isFinal && order.processingVehicle != null) {
                dispatchContext.onVehicleFree(order.processingVehicle!!)
            }
            return
        }
        val becameDispatchable = order.name !in dispatchable
        dispatchable[order.name] = order
        if (becameDispatchable) trigger.requestForNewOrder()
    }

    private fun releaseFinishedSequence(event: OrderSequenceEvent) {
        val sequence = event.current ?: return
        if (!sequence.finished || event.previous?.finished == true) return
        plant.vehicles().filter { it.orderSequence == sequence.name }.forEach { vehicle ->
            plant.updateVehicle(vehicle.name) { it.copy(orderSequence = null) }
        }
        trigger.request()
    }

    private companion object {
        const val SAMPLE_SIZE = 5
    }

    private fun scheduleSweep() {
        sweep = context.schedule(options.sweepIntervalMillis) {
            val cutoff = context.now().toEpochMilli() - options.sweepAgeMillis
            orders.removeFinishedBefore(cutoff)
            sequences.removeFinishedBefore(cutoff)
            scheduleSweep()
        }
    }
}
