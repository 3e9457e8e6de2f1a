package org.ktcs.kernel.scheduling

/**
 * Deadlock avoidance: no grant may close a cycle of vehicles waiting for each other (see the developer's guide,
 * "Traffic rule").
 *
 * Each client needs its look-ahead A: the next step it claimed and has not been granted yet, extended over every
 * further step on a two-way stretch (where vehicles could meet head-on) and, at the end of its claim, by the way out
 * of the point where it will stop ([ExitCorridors]); a client without a claim needs the way out of where it stands.
 * It holds H, what the scheduler gave it. Client u waits for w when A(u) ∩ H(w) ≠ ∅. A grant of X to v changes
 * H(v) to H(v) ∪ X and A(v) to the look-ahead after X; it is made only if no client v then waits for (transitively)
 * waits for v. The check walks forward from v over "the holders of what this one needs next", so it costs the chain
 * of vehicles queued ahead of v, not the plant.
 *
 * Keys are resource names plus the names of SAME_DIRECTION_ONLY blocks (treated as exclusive here, a conservative
 * simplification); SINGLE_VEHICLE_ONLY blocks are expanded to their members by the caller.
 */
internal class RouteSafety(
    private val exits: ExitCorridors,
    private val holdings: (String) -> Set<String>,
    private val holders: (String) -> Collection<String>,
) {

    private val routes = HashMap<String, ArrayDeque<Step>>()
    private val wayOut = HashMap<String, Set<String>>()

    private class Step(val keys: Set<String>, val twoWay: Boolean)

    /** How many grants were held back because they would have closed a cycle. */
    var heldBack = 0L
        private set

    fun isPoint(name: String): Boolean = exits.isPoint(name)

    /** Replaces [client]'s claim with [route] (keys per step, in driving order) ending at [end]. */
    fun claim(client: String, route: List<Set<String>>, end: String?) {
        routes[client] = route.mapTo(ArrayDeque()) { keys -> Step(keys, keys.any(exits::isTwoWay)) }
        wayOut[client] = end?.let(exits::from).orEmpty()
    }

    /** [client] has no claim any more; it needs the way out of wherever it stands. */
    fun unclaim(client: String) {
        routes.remove(client)
        standing(client)
    }

    /** Recomputes the way out of a client without a claim after what it holds changed. */
    fun standing(client: String) {
        if (client in routes) return
        val points = holdings(client).filter(exits::isPoint)
        wayOut[client] = points.flatMapTo(HashSet()) { exits.from(it) }
    }

    fun remove(client: String) {
        routes.remove(client)
        wayOut.remove(client)
    }

    /** [client] was granted [keys]: the first claimed step with exactly these keys is no longer needed. */
    fun granted(client: String, keys: Set<String>) {
        val route = routes[client] ?: return
        val index = route.indexOfFirst { it.keys == keys }
        if (index >= 0) route.removeAt(index)
    }

    /**
     * Whether granting [keys] to [client] keeps the waits free of cycles, once the client has driven up to them and
     * holds [keys] and what its length still covers behind it ([behind]); what it holds until then it gives up as it
     * drives, so waits for that resolve by themselves.
     */
    fun mayGrant(client: String, keys: Set<String>, behind: Set<String>): Boolean {
        val held = keys + behind
        val ahead = lookAhead(client, skipping = keys)
        val seen = HashSet<String>()
        val queue = ArrayDeque<String>()
        fun enqueueHoldersOf(needed: Set<String>) {
            for (key in needed) for (holder in holders(key)) if (holder != client && seen.add(holder)) queue += holder
        }
        enqueueHoldersOf(ahead)
        while (queue.isNotEmpty()) {
            val next = lookAhead(queue.removeFirst())
            if (next.any { it in held }) {
                heldBack++
                return false
            }
            enqueueHoldersOf(next)
        }
        return true
    }

    /** What [client] needs next as deadlock avoidance sees it, for diagnostics. */
    fun needs(client: String): Set<String> = lookAhead(client)

    // The next step, every following step while on a two-way stretch, and the way out at the end of the claim.
    private fun lookAhead(client: String, skipping: Set<String>? = null): Set<String> {
        val route = routes[client] ?: return wayOut[client].orEmpty()
        val ahead = HashSet<String>()
        var skipped = skipping == null
        for (step in route) {
            if (!skipped && step.keys == skipping) {
                skipped = true
                continue
            }
            ahead += step.keys
            if (!step.twoWay) return ahead
        }
        ahead += wayOut[client].orEmpty()
        return ahead
    }
}
