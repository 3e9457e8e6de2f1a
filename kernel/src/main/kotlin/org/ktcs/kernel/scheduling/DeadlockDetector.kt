package org.ktcs.kernel.scheduling

import org.ktcs.api.scheduling.SchedulerWaits

/**
 * Vehicles each waiting for what the next one holds, the last for the first, so none of them can ever move on.
 *
 * @property vehicles in waiting order.
 * @property resources the contested resources: what each vehicle wants and the next one holds.
 */
data class Deadlock(val vehicles: List<String>, val resources: Set<String>)

/** A proposal to break a deadlock: route [vehicle] anew, around [resourcesToAvoid]. */
data class DeadlockResolution(val vehicle: String, val resourcesToAvoid: Set<String>)

/** Finds deadlocks among the clients of a scheduler, and proposes how to break them. */
object DeadlockDetector {
    /** The deadlocks in a scheduler's [allocations] and [pending] requests (see [SchedulerWaits.of]). */
    fun detect(allocations: Map<String, Set<String>>, pending: Map<String, List<Set<String>>>): List<Deadlock> =
        detect(WaitForGraph(SchedulerWaits.of(allocations, pending)))

    /** The deadlocks of [graph], one per cycle it reports (see [WaitForGraph.cycles]). */
    fun detect(graph: WaitForGraph): List<Deadlock> = graph.cycles().map { cycle ->
        Deadlock(cycle, cycle.indices.flatMapTo(LinkedHashSet()) { graph.contested(cycle[it], cycle.next(it)) })
    }

    /**
     * Proposals to break [deadlock], best first: each vehicle of the cycle may take another way around what the
     * next vehicle holds of its request; vehicles with the fewest resources to avoid come first, since the router is
     * most likely to find a way around them, then cycle order.
     */
    fun resolutions(deadlock: Deadlock, graph: WaitForGraph): List<DeadlockResolution> {
        val cycle = deadlock.vehicles
        return cycle.indices
            .map { DeadlockResolution(cycle[it], graph.contested(cycle[it], cycle.next(it))) }
            .filter { it.resourcesToAvoid.isNotEmpty() }
            .sortedBy { it.resourcesToAvoid.size }
    }

    /** The best of [resolutions], or `null` if [deadlock] is not (any longer) one in [graph]. */
    fun resolve(
        deadlock: Deadlock,
        graph: WaitForGraph,
    ): DeadlockResolution? = resolutions(deadlock, graph).firstOrNull()

    private fun List<String>.next(index: Int): String = this[(index + 1) % size]
}
