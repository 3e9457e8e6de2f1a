package org.ktcs.kernel.core

import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.dispatching.RecoveryEvaluator
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.event.UserNotification
import org.ktcs.api.kernel.Cancellable
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.PlantModel
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
import org.ktcs.kernel.events.KernelEvents
import org.ktcs.kernel.events.NotificationLog
import org.ktcs.kernel.orders.HistoryCodes
import org.ktcs.kernel.orders.OrderLifecycle
import org.ktcs.kernel.orders.OrderSequences
import org.ktcs.kernel.orders.TransportOrders
import org.ktcs.kernel.store.CommitBarrier
import org.ktcs.kernel.vehicles.DriverAttachments
import org.ktcs.kernel.workingset.NamesUsed
import org.ktcs.kernel.workingset.PlantView

/**
 * The kernel's state and the operations on it, wired together: plant, orders, sequences, vehicle controllers and
 * the strategies. Everything here runs in [context]; the services in `kernel.services` are the way in from outside.
 *
 * The kernel state has one door: the mutable state ([KernelState]) is private to `core`; other code reads through
 * read-only views ([plant], [orders], [sequences], [controllers], ...) and changes state only through operations
 * (methods here, [requests] for what operators and hosts ask, [restoration] for the state store), so every rule
 * about a change lives in one place.
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
    private val trigger = DispatchTrigger(
        context,
        dispatcherProvider,
        options.redispatchIntervalMillis,
        options.newOrderDispatchDelayMillis,
    )
    private val state =
        KernelState(context, model, options, driverFactories, { scheduler }, { router }, trigger::requestForVehicle)
    private val intake = OrderIntake(state)
    private val lifecycle = OrderLifecycle(state.orders, state.sequences, { router }, options.dismissUnroutableOrders)
    private val dispatching = KernelDispatchContext(this, state)

    // snippet:kernel-views

    /** The kernel's events: listen (kernel components) or subscribe (clients); only the kernel publishes. */
    val events: KernelEvents get() = state.events

    /** The most recent user notifications; publish through [publishNotification]. */
    val notifications: NotificationLog get() = state.notifications

    /** The plant as it is now (read-only; changes go through the kernel's operations). */
    val plant: PlantView get() = state.plant

    /** The transport orders (read-only). */
    val orders: TransportOrders get() = state.orders

    /** The order sequences (read-only). */
    val sequences: OrderSequences get() = state.sequences

    /** Where the generation of object names stands (read-only). */
    val names: NamesUsed get() = state.names

    /** The vehicles' drivers (read-only; attach, enable and message them through [requests]). */
    val controllers: DriverAttachments get() = state.controllers

    /** What the dispatcher sees of the kernel and may do with it. */
    val dispatchContext: DispatchContext get() = dispatching
    // end-snippet

    /** Where requests wait for their changes to be committed to the state store (none without a store). */
    var commits: CommitBarrier = CommitBarrier.NONE
        private set

    /** The dispatcher in use (the default one, or one an extension put in its place). */
    val dispatcher: Dispatcher get() = dispatcherProvider()

    private val dispatchable = DispatchableOrders(state, trigger) { dispatching.onVehicleFree(it) }
    private val plantChanges = PlantChanges(this, state, dispatchable)
    private val agreement = StateAgreement(state) { scheduler }
    private var sweep: Cancellable? = null
    private val deadlockWatchdog = DeadlockWatchdog(this, state)

    /** What the deadlock watchdog has done so far. */
    val watchdog: WatchdogFigures get() = deadlockWatchdog

    /** What an operator or host may ask directly (assign now, vehicles' settings, locks ...), with its rules. */
    val requests = OperatorRequests(this, state)

    /** How the state store puts a previous run back (only before and right after [start]). */
    val restoration = KernelRestoration(this, state, lifecycle)
    private val operationsWatchdog = OperationsWatchdog(this, state)

    init {
        state.events.listen(lifecycle::onEvent)
        state.events.listen(dispatchable::track)
    }

    /** Starts the strategies, the vehicles and the periodic tasks; call in the kernel context. */
    fun start() {
        router.initialize()
        router.updateTopology(plant.layoutWithLocks())
        scheduler.initialize()
        recoveryEvaluator.initialize()
        dispatcherProvider().initialize()
        state.controllers.start(options.enableDriversOnStart, options.initialIntegrationLevel)
        plantChanges.announceTrafficLimits()
        trigger.start()
        deadlockWatchdog.start()
        operationsWatchdog.start()
        scheduleSweep()
        trigger.request()
    }

    fun stop() {
        sweep?.cancel()
        deadlockWatchdog.stop()
        operationsWatchdog.stop()
        trigger.stop()
        state.controllers.stop()
        dispatcherProvider().terminate()
        recoveryEvaluator.terminate()
        scheduler.terminate()
        router.terminate()
    }

    fun dispatch() = trigger.request()

    /** Publishes [notification] to the operators (logged and kept among the recent ones). */
    fun publishNotification(notification: UserNotification) = state.notifications.publish(notification)

    /** Publishes a notification from [source], stamped now. */
    fun publishNotification(source: String?, level: NotificationLevel, text: String) =
        state.notifications.publish(source, level, text)

    /** From now on, requests wait for their changes to be committed to [barrier] (the state store). */
    fun commitThrough(barrier: CommitBarrier) {
        commits = barrier
    }

    /**
     * Where facts kept in more than one place disagree (which vehicle does which order; which resources a vehicle
     * holds); empty when all copies agree. For tests and diagnostics.
     */
    fun disagreements(): List<String> = agreement.disagreements()

    /** Looks for deadlocks now (the watchdog also does so periodically). */
    fun checkForDeadlocks() = deadlockWatchdog.check()

    /**
     * Routes [vehicle] again around the resources in [avoid] where possible (it keeps its route otherwise); whether
     * its way changed.
     */
    fun reroute(vehicle: String, avoid: Set<String>): Boolean = state.controllers.controller(vehicle).reroute(avoid)

    /** Sends [vehicle] on through the free park point [park], avoiding [occupied] on the way there. */
    fun retreat(vehicle: String, park: String, occupied: Set<String>): Boolean =
        state.controllers.controller(vehicle).retreat(park, occupied)

    /** Hands the router the current layout again (path and location locks included). */
    fun updateRoutingTopology() = router.updateTopology(state.plant.layoutWithLocks())

    /** The DISPATCHABLE orders, oldest first (a read-only view). */
    fun dispatchableOrders(): Collection<TransportOrder> = dispatchable.all()

    /** Puts back a DISPATCHABLE order read from the state store at start (no event: nothing changed). */
    internal fun restoreDispatchable(order: TransportOrder) = dispatchable.restore(order)

    fun createTransportOrder(creation: TransportOrderCreation): TransportOrder = intake.createTransportOrder(creation)

    fun createOrderSequence(creation: OrderSequenceCreation): OrderSequence = intake.createOrderSequence(creation)

    fun markSequenceComplete(name: String) {
        state.sequences.update(name) {
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
        state.orders.update(order) {
            it.copy(
                processingVehicle = vehicle,
                driveOrders = driveOrders,
                history = it.history + HistoryEntry(context.now(), HistoryCodes.ORDER_ASSIGNED, vehicle),
            )
        }
        state.orders.transition(order, TransportOrderState.BEING_PROCESSED)
        current.wrappingSequence?.let { sequence ->
            state.sequences.update(sequence) { it.copy(processingVehicle = vehicle) }
        }
        state.controllers.controller(vehicle).assign(state.orders.require(order))
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
            if (current.state != TransportOrderState.WITHDRAWN) {
                state.orders.transition(order, TransportOrderState.WITHDRAWN)
            }
            state.orders.transition(order, TransportOrderState.FAILED, "withdrawn")
            return
        }
        if (disableVehicle) state.controllers.setIntegrationLevel(vehicle, IntegrationLevel.TO_BE_RESPECTED)
        state.controllers.controller(vehicle).withdraw(immediate)
    }

    /**
     * Locks or unlocks a path and updates the routing topology; vehicles whose remaining route uses a path that
     * was just locked are routed around it where possible (otherwise they keep their route, as openTCS's
     * IGNORE_PATH_LOCKS strategy does, and the lock applies to new routes).
     */
    fun setPathLocked(path: String, locked: Boolean) = plantChanges.setPathLocked(path, locked)

    /**
     * Replaces the plant with [model] when nothing is under way: no transport order that is not final, no order
     * sequence that is not finished, no vehicle moving. Drops final orders and finished sequences, then starts the
     * new vehicles. A model that differs only in path locks, path velocities and location locks is applied at
     * once, also while vehicles drive: vehicles keep running and those whose route uses a newly locked path are
     * routed around it. [persist] runs once the model is accepted and before it applies; if it throws, the plant
     * stays as it was.
     */
    fun replacePlantModel(model: PlantModel, persist: (PlantModel) -> Unit = {}) = plantChanges.replace(model, persist)

    private fun scheduleSweep() {
        sweep = context.schedule(options.sweepIntervalMillis) {
            val cutoff = context.now().toEpochMilli() - options.sweepAgeMillis
            state.orders.removeFinishedBefore(cutoff)
            state.sequences.removeFinishedBefore(cutoff)
            scheduleSweep()
        }
    }
}
