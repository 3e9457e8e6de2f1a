package org.ktcs.kernel.core

import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.kernel.Cancellable
import org.ktcs.kernel.scheduling.Deadlock
import org.ktcs.kernel.scheduling.DeadlockDetector
import org.ktcs.kernel.scheduling.DefaultScheduler
import org.ktcs.kernel.scheduling.WaitForGraph
import org.slf4j.LoggerFactory

/**
 * Looks for vehicles that wait for each other in a cycle, reports each deadlock once (user notification and log
 * line naming vehicles and resources) and breaks it by routing one of the vehicles around what blocks it. Also sends
 * idle vehicles that stand in a waiting vehicle's way elsewhere ([IdleBlockers]).
 * The check costs in proportion to the waiting vehicles, not the plant.
 */
class DeadlockWatchdog(private val kernel: KernelCore) {
    private val log = LoggerFactory.getLogger(DeadlockWatchdog::class.java)
    private var next: Cancellable? = null
    private var reported = emptySet<Set<String>>()
    private var unresolved = emptySet<Set<String>>()
    private val idleBlockers = IdleBlockers(kernel)

    var detected = 0
        private set
    var resolved = 0
        private set

    /** How many idle vehicles were sent out of the way of waiting ones. */
    val idleVehiclesMoved: Int get() = idleBlockers.moved

    fun start() {
        val interval = kernel.options.deadlockCheckIntervalMillis
        if (interval <= 0) return
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
        // The default scheduler also knows waits caused by same-direction blocks, which its allocations do not show.
        val graph = (kernel.scheduler as? DefaultScheduler)?.waitForGraph()
            ?: WaitForGraph.of(kernel.scheduler.allocations(), kernel.scheduler.pendingAllocations())
        val deadlocks = DeadlockDetector.detect(graph)
        val current = deadlocks.mapTo(HashSet()) { it.vehicles.toSet() }
        // Each deadlock is reported once, but breaking it is tried at every check for as long as it lasts: a vehicle
        // that could not be routed around it before may be now.
        val stillUnresolved = HashSet<Set<String>>()
        deadlocks.forEach { deadlock ->
            val vehicles = deadlock.vehicles.toSet()
            val new = vehicles !in reported
            if (new) {
                detected++
                report(deadlock)
            } else if (vehicles !in unresolved) {
                return@forEach
            }
            if (DeadlockDetector.resolutions(deadlock, graph).any {
                    kernel.controllers.controller(it.vehicle).reroute(it.resourcesToAvoid)
                }
            ) {
                resolved++
                log.info("deadlock resolved by rerouting: vehicles={}", deadlock.vehicles)
            } else {
                if (new) log.warn("deadlock not resolved yet, no way around it: vehicles={}", deadlock.vehicles)
                stillUnresolved += vehicles
            }
        }
        reported = current
        unresolved = stillUnresolved
        idleBlockers.check(graph)
    }

    private fun report(deadlock: Deadlock) {
        val text = "deadlock: vehicles ${deadlock.vehicles.joinToString(
            " -> ",
        )} wait for each other; contested resources ${deadlock.resources.sorted().joinToString()}"
        kernel.notifications.publish("deadlock watchdog", NotificationLevel.IMPORTANT, text)
    }
}
