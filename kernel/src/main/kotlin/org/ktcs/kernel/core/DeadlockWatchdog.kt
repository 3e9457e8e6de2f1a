package org.ktcs.kernel.core

import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Cancellable
import org.ktcs.kernel.scheduling.Deadlock
import org.ktcs.kernel.scheduling.DeadlockDetector
import org.ktcs.kernel.scheduling.WaitForGraph
import org.slf4j.LoggerFactory

/**
 * Looks for vehicles that wait for each other in a cycle, reports each deadlock once (user notification and log
 * line naming vehicles and resources) and breaks it by routing one of the vehicles around what blocks it. Also sends
 * idle vehicles that stand in a waiting vehicle's way elsewhere ([IdleBlockers]), and first makes a vehicle yield to a
 * fresh claim that waits for itself ([BlockedClaims]).
 * The check costs in proportion to the waiting vehicles, not the plant.
 */
class DeadlockWatchdog(private val kernel: KernelCore, private val state: KernelState) : WatchdogFigures {
    private val log = LoggerFactory.getLogger(DeadlockWatchdog::class.java)
    private var next: Cancellable? = null
    private val stuck = StuckStates()
    private val idleBlockers = IdleBlockers(kernel, state)
    private val retreating = Retreats(kernel)
    private val blockedClaims = BlockedClaims(kernel, state)
    private val moving = MovingVehicles(state, MOVING_PATIENCE_MILLIS / checkPeriodMillis())

    override val detected: Int get() = stuck.detected

    override val resolved: Int get() = stuck.resolved

    override val idleVehiclesMoved: Int get() = idleBlockers.moved

    override val retreats: Int get() = retreating.sent

    override val claimYields: Int get() = blockedClaims.yields

    fun start() {
        // The period is vehicle time: at time factor 100 a check every kernel second would let vehicles drive 100 s
        // between checks, and a retreat's cool-down of 60 checks outlast any stall timeout.
        val options = kernel.options
        if (options.deadlockCheckIntervalMillis <= 0) return
        val interval = (options.deadlockCheckIntervalMillis / options.vehicleTimeFactor).toLong().coerceAtLeast(1)
        next = kernel.context.schedule(interval) {
            // A failing check is a bug to log, but must not end all later checks.
            try {
                check()
            } finally {
                start()
            }
        }
    }

    fun stop() {
        next?.cancel()
    }

    /** Finds and handles the current deadlocks. */
    fun check() {
        blockedClaims.check(retreating)
        // A fleet held back by deadlock avoidance gets moving by a retreat first: planned avoidance, not a deadlock
        // found (a cycle it breaks is not counted; one it does not break is found at the next check).
        if (retreating.check()) return
        // Asks the scheduler's interface only, so a replaced scheduler keeps the watchdog working.
        val waits = kernel.scheduler.waitsFor()
        val graph = WaitForGraph(waits)
        // A vehicle carrying out a command does not wait: a cycle through it may end when it arrives.
        moving.startCheck()
        val stuckGraph = WaitForGraph(waits.filterKeys { !moving.isMoving(it) })
        val deadlocks = DeadlockDetector.detect(stuckGraph)
        val allocations by lazy { kernel.scheduler.allocations() }
        val held = { vehicle: String -> allocations[vehicle].orEmpty() }
        stuck.startCheck(held) { it in stuckGraph.edges }
        // Each deadlock is reported once; breaking it is tried at once and then, for as long as nothing changes, at
        // growing intervals: a vehicle that could not be routed around it before may be now.
        deadlocks.forEach { deadlock ->
            val verdict = stuck.observe(deadlock.vehicles, held)
            if (verdict.isNew) report(deadlock)
            if (!verdict.resolveNow) return@forEach
            if (breakDeadlock(deadlock, stuckGraph, again = !verdict.isNew)) {
                stuck.rerouted(deadlock.vehicles)
                log.info("deadlock: rerouted a vehicle to break it: vehicles={}", deadlock.vehicles)
            } else if (verdict.isNew) {
                log.warn("deadlock not resolved yet, no way around it: vehicles={}", deadlock.vehicles)
            }
        }
        idleBlockers.check(graph)
    }

    // Routes one vehicle of [deadlock] around what it waits for, else sends one off the lanes through a free park
    // point (a retreat); a knot that came back after that ([again]) gets the retreat first, since routing around
    // it did not last.
    private fun breakDeadlock(deadlock: Deadlock, graph: WaitForGraph, again: Boolean): Boolean {
        if (again && retreating.breakCycle(deadlock.vehicles)) return true
        return DeadlockDetector.resolutions(deadlock, graph).any { kernel.reroute(it.vehicle, it.resourcesToAvoid) } ||
            retreating.breakCycle(deadlock.vehicles)
    }

    // A watchdog run by hand (period 0) counts its checks as if made at the default period.
    private fun checkPeriodMillis(): Long = kernel.options.deadlockCheckIntervalMillis.takeIf { it > 0 } ?: 1_000L

    private fun report(deadlock: Deadlock) {
        val text = "deadlock: vehicles ${deadlock.vehicles.joinToString(
            " -> ",
        )} wait for each other; contested resources ${deadlock.resources.sorted().joinToString()}"
        state.notifications.publish("deadlock watchdog", NotificationLevel.IMPORTANT, text)
    }

    private companion object {
        /** Vehicle time without a command reported done after which a vehicle with commands counts as stopped. */
        const val MOVING_PATIENCE_MILLIS = 60_000L
    }
}
