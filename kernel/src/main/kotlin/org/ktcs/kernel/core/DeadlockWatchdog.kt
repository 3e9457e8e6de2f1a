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
 * line naming vehicles and resources) and breaks it by routing one of the vehicles around what blocks it.
 * The check costs in proportion to the waiting vehicles, not the plant.
 */
class DeadlockWatchdog(private val kernel: KernelCore) {
    private val log = LoggerFactory.getLogger(DeadlockWatchdog::class.java)
    private var next: Cancellable? = null
    private var reported = emptySet<Set<String>>()

    var detected = 0
        private set
    var resolved = 0
        private set

    fun start() {
        val interval = kernel.options.deadlockCheckIntervalMillis
        if (interval <= 0) return
        next = kernel.context.schedule(interval) {
            check()
            start()
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
        deadlocks.filter { it.vehicles.toSet() !in reported }.forEach { deadlock ->
            detected++
            report(deadlock)
            if (DeadlockDetector.resolutions(deadlock, graph).any {
                    kernel.controllers.controller(it.vehicle).reroute(it.resourcesToAvoid)
                }
            ) {
                resolved++
                log.info("deadlock resolved by rerouting: vehicles={}", deadlock.vehicles)
            }
        }
        reported = current
    }

    private fun report(deadlock: Deadlock) {
        val text = "deadlock: vehicles ${deadlock.vehicles.joinToString(
            " -> ",
        )} wait for each other; contested resources ${deadlock.resources.sorted().joinToString()}"
        kernel.notifications.publish("deadlock watchdog", NotificationLevel.IMPORTANT, text)
    }
}
