package org.ktcs.kernel.core

/**
 * The deadlock watchdog's memory of stuck states. A stuck state is a group of vehicles found in wait-for cycles that
 * has not changed since: none of them has moved (given up or taken a resource) or stopped waiting. Cycles that share
 * a vehicle of a stuck state belong to it, so one knot of vehicles that the cycle search shows as different cycles
 * at different checks counts once. Breaking a stuck state is tried at once, then again after 1, 2, 4, ... checks (at
 * most [maxBackOff]) for as long as it lasts: a reroute that changed nothing is not repeated at every check.
 */
internal class StuckStates(private val maxBackOff: Int = 8) {
    private class State {
        var backOff = 1
        var nextAttempt = 0L
        var rerouted = false
    }

    /** What the watchdog should do about one cycle: [isNew] report it, [resolveNow] try to break it. */
    data class Verdict(val isNew: Boolean, val resolveNow: Boolean)

    private val stateOf = HashMap<String, State>()
    private val heldWhenStuck = HashMap<String, Set<String>>()
    private var checks = 0L

    /** How many distinct stuck states were found. */
    var detected = 0
        private set

    /** How many stuck states ended after a vehicle of theirs was rerouted. */
    var resolved = 0
        private set

    /**
     * Starts a check: forgets every stuck state one of whose vehicles now holds something else than when it was
     * found ([held]) or no longer waits ([isWaiting]).
     */
    fun startCheck(held: (String) -> Set<String>, isWaiting: (String) -> Boolean) {
        checks++
        val ended = stateOf.filter { (vehicle, _) -> !isWaiting(vehicle) || held(vehicle) != heldWhenStuck[vehicle] }
            .values.toSet()
        if (ended.isEmpty()) return
        resolved += ended.count { it.rerouted }
        stateOf.values.removeAll(ended)
        heldWhenStuck.keys.retainAll(stateOf.keys)
    }

    /** Files the cycle of [vehicles] under its stuck state, a new one if none of them is in one yet. */
    fun observe(vehicles: List<String>, held: (String) -> Set<String>): Verdict {
        val known = vehicles.firstNotNullOfOrNull(stateOf::get)
        val state = known ?: State().also { detected++ }
        for (vehicle in vehicles) {
            if (vehicle !in stateOf) {
                stateOf[vehicle] = state
                heldWhenStuck[vehicle] = held(vehicle)
            }
        }
        val due = checks >= state.nextAttempt
        if (due) {
            state.nextAttempt = checks + state.backOff
            state.backOff = minOf(state.backOff * 2, maxBackOff)
        }
        return Verdict(isNew = known == null, resolveNow = due)
    }

    /** A vehicle of the stuck state of [vehicles] was rerouted. */
    fun rerouted(vehicles: List<String>) {
        vehicles.firstNotNullOfOrNull(stateOf::get)?.rerouted = true
    }
}
