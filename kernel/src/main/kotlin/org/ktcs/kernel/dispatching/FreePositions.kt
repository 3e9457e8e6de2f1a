package org.ktcs.kernel.dispatching

import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.Vehicle

/**
 * Which points and locations a vehicle may be sent to park or recharge: none that another vehicle stands on, and
 * none that an unfinished order (a vehicle's, a dispatchable one, or one assigned earlier in this run) ends at.
 */
internal class FreePositions(private val run: DispatchRun) {
    // Lazy: most runs find no idle vehicle and never ask.
    private val occupants: Map<String, List<String>> by lazy {
        run.vehicles
            .filter { it.integrationLevel != IntegrationLevel.TO_BE_IGNORED && it.currentPosition != null }
            .groupBy({ it.currentPosition!! }, { it.name })
    }

    private val targeted: Set<String> by lazy {
        buildSet {
            run.vehicles.mapNotNull { it.transportOrder?.let(run::order) }
                .filter { !it.state.isFinal }
                .forEach { addAll(finalTargets(it)) }
            run.dispatchableOrders.forEach { addAll(finalTargets(it)) }
        }
    }

    /** Whether [name] (a point or location) is neither occupied by another vehicle than [vehicle] nor targeted. */
    fun isFreeFor(name: String, vehicle: Vehicle): Boolean =
        occupants[name].orEmpty().all { it == vehicle.name } && name !in targeted && name !in run.claimedTargets
}
