package org.ktcs.kernel.dispatching

import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.api.dispatching.RecoveryEvaluator

/**
 * openTCS's default dispatching strategy, in one pass per [dispatch]:
 * 1. vehicles bound to an order sequence get its next dispatchable order;
 * 2. free orders go to available vehicles (see [DispatcherConfiguration] for the rankings and the window of orders a
 *    vehicle chooses among), a vehicle busy with a dispensable order taking a non-dispensable one in preference to
 *    staying on it;
 * 3. idle vehicles with degraded energy get a recharge order, assigned at once;
 * 4. idle vehicles that are not parked get a park order, assigned at once (and parked ones a better park point, if
 *    configured).
 *
 * A run only looks at available vehicles and dispatchable orders, routes a vehicle–order pair at most once, and with
 * rankings that need no route (the defaults) routes candidates one by one until the first acceptable one. Delays
 * count against [DispatchContext.clock]; the dispatcher keeps no timers, so the kernel must run it again when a delay
 * may have passed. Between runs it remembers the last reason recorded per waiting order, and what the last run left
 * ([FreeOrderAssignment.settled]) for a run on changes ([dispatchChanges]): while no vehicle can take any waiting order, such a run looks
 * only at the new orders, so creating an order costs the same with ten orders waiting as with ten thousand; when a
 * vehicle can, it assigns as a full run does but gives reasons again only where they may have changed.
 */
class DefaultDispatcher(
    private val configuration: DispatcherConfiguration,
    private val context: DispatchContext,
    private val recovery: RecoveryEvaluator,
) : IncrementalDispatcher {
    private val deferrals = DeferralLog(context)
    private val passOvers = PassOvers(configuration.orderCandidateWindow)
    private var settled: WaitingReasons.Given? = null

    /** How many runs on changes did not have to be full ones (for tests). */
    internal var incrementalRuns: Int = 0
        private set

    override fun dispatch() = run(newOrders = null)

    override fun dispatchChanges(newOrders: Collection<String>) = run(newOrders)

    private fun run(newOrders: Collection<String>?) {
        val run = DispatchRun(context, configuration, recovery)
        val availability = VehicleAvailability.of(run)
        val checks = CandidateChecks(run, availability)
        SequenceSuccessors(run, availability, checks, deferrals).assign()
        val freeOrders = FreeOrderAssignment(run, availability, checks, deferrals, passOvers)
        val previous = settled
        settled = null
        if (newOrders != null && previous != null && freeOrders.assignNew(newOrders, previous)) {
            incrementalRuns++
        } else {
            freeOrders.assign()
        }
        handleIdleVehicles(run, availability)
        // Only a run that read the orders knows which are still waiting; the others leave the log as it is.
        // Runs on changes leave that to the full ones (at the latest the periodic run).
        if (run.ordersRead && newOrders == null) {
            val waiting = run.dispatchableOrders.mapTo(HashSet()) { it.name }
            deferrals.retainOnly(waiting)
            passOvers.retainOnly(waiting)
        }
        settled = freeOrders.settled()
    }

    private fun handleIdleVehicles(run: DispatchRun, availability: VehicleAvailability) {
        if (!configuration.rechargeIdleVehicles && !configuration.parkIdleVehicles) return
        val idle = IdleVehicles(run, availability)
        val free = FreePositions(run)
        val placer = IdleOrderPlacer(run)
        if (configuration.rechargeIdleVehicles) IdleVehicleRecharging(run, idle, free, placer).run()
        if (configuration.parkIdleVehicles) IdleVehicleParking(run, idle, free, placer).run()
    }
}
