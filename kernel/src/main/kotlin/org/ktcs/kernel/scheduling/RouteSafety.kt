package org.ktcs.kernel.scheduling

/**
 * Deadlock avoidance: no grant may close a cycle of vehicles waiting for each other (see the developer's guide,
 * "Traffic rule").
 *
 * Each client has a look-ahead: the next step it claimed and has not been granted yet, extended over every further
 * step on a two-way stretch (where vehicles could meet head-on), and at the end of its claim the way out of the point
 * where it will stop ([ExitCorridors]: a corridor it needs, then any one of the ways on). A client without a claim
 * has the way out of where it stands. Client u waits for w when w holds what u's look-ahead needs (for the ways on:
 * when every one of them is held). A grant of X to v makes v hold X and what its length covers behind X once it has
 * driven there, and moves v's look-ahead past X; it is made only if v would then not wait, through any chain of
 * waits, for itself. The check walks forward from v over the holders of what each vehicle needs next, so it costs the
 * queue of vehicles ahead of v, not the plant.
 *
 * Keys are resource names plus the names of SAME_DIRECTION_ONLY blocks (treated as exclusive here, a conservative
 * simplification) and, per two-way corridor a step drives along, its need key ([Corridors.needKey]): a vehicle
 * heading one way along a corridor holds the need keys of the other ways in ([Corridors.heldKeys]), so a vehicle
 * waiting to enter against it waits for it. SINGLE_VEHICLE_ONLY blocks are expanded to their members by the caller.
 */
internal class RouteSafety(
    private val exits: ExitCorridors,
    private val holdings: (String) -> Set<String>,
    private val holders: (String) -> Collection<String>,
    private val requesters: (key: String) -> Collection<Requester> = { emptyList() },
) {
    private val routes = HashMap<String, ArrayDeque<ClaimedStep>>()
    private val wayOut = HashMap<String, Exit>()

    private val assumed = AssumedGrants(holdings, holders)

    private val versions = ClientVersions()

    // Per client, the local rule's last refusal of its grant, if the client has not been granted anything since.
    private val refusals = KeptRefusals(versions)

    // Per client, its look-ahead as it stands: a walk visits the vehicles queued ahead again and again, unchanged.
    private val lookAheads = HashMap<String, KnownLookAhead>()

    /** How many grants were held back because they would have closed a cycle. */
    var heldBack = 0L
        private set

    /** How many grants were held back because they would have left a dead hole ([leavesDeadHole]). */
    var deadHolesHeldBack = 0L
        private set

    fun isPoint(name: String): Boolean = exits.isPoint(name)

    fun isDeadEnd(point: String): Boolean = exits.isDeadEnd(point)

    /**
     * Replaces [client]'s claim with [route] (keys per step, in driving order) ending at [end]; [stops] names, per
     * step, the point where the vehicle stops for an operation at its end (null: it drives on).
     */
    fun claim(client: String, route: List<Set<String>>, stops: List<String?>, end: String?) {
        changed(client)
        routes[client] = route.zip(stops).mapTo(ArrayDeque()) { (keys, stop) ->
            ClaimedStep(keys, keys.any(exits::isTwoWay), stop?.let(exits::from), stop != null && exits.isDeadEnd(stop))
        }
        wayOut[client] = end?.let(exits::from) ?: Exit.NONE
    }

    fun isLocation(name: String): Boolean = exits.isLocation(name)

    /** [client] has no claim any more; it needs the way out of wherever it stands. */
    fun unclaim(client: String) {
        routes.remove(client)
        standing(client)
    }

    /** Recomputes the way out of a client without a claim after what it holds changed. */
    fun standing(client: String) {
        changed(client)
        if (client in routes) return
        val point = holdings(client).singleOrNull(exits::isPoint)
        wayOut[client] = point?.let(exits::from) ?: Exit.NONE
    }

    fun remove(client: String) {
        routes.remove(client)
        wayOut.remove(client)
        changed(client)
        refusals.forget(client)
    }

    /** [client] was granted [keys]: the first claimed step with exactly these keys is no longer needed. */
    fun granted(client: String, keys: Set<String>) {
        changed(client)
        refusals.forget(client)
        val index = claimedStep(client, keys)
        if (index >= 0) routes[client]?.removeAt(index)
    }

    // The index of [client]'s first claimed step with exactly [keys] (corridor need keys aside), -1 if none.
    private fun claimedStep(client: String, keys: Set<String>): Int {
        val physical = physicalOf(keys)
        return routes[client]?.indexOfFirst { it.physical == physical } ?: -1
    }

    /**
     * Whether granting [keys] to [client] keeps the waits free of cycles, once the client has driven up to them and
     * holds [keys] and what its length still covers behind it ([behind]); what it holds until then it gives up as it
     * drives, so waits for that resolve by themselves. A step onto the mouth of a free dead-end bay that the claim
     * turns back in is judged as the client will stand in the bay ([behindInBay]: what its length covers there, given
     * the bay's step; by default the mouth too).
     */
    fun mayGrant(
        client: String,
        keys: Set<String>,
        behind: Set<String>,
        behindInBay: (bay: Set<String>) -> Set<String> = { behind + physicalOf(keys) },
    ): Boolean {
        if (!refusals.stillHolds(client, keys, behind)) {
            val held = keysHeldAfter(keys, behind)
            val walk = walk(client, held)
            val witnesses = HashSet<String>()
            if (!walk.isBlocked(lookAhead(client, keys, held), client) ||
                maySafelyStopInBay(client, keys, behindInBay, witnesses)
            ) {
                refusals.forget(client)
                return true
            }
            refusals.keep(client, keys, behind, walk.reached() + witnesses + client)
        }
        heldBack++
        return false
    }

    /**
     * Tells the check that what [client] holds has changed; its claim, grants and way out it sees itself. Whatever
     * changes what a client holds must call this before the next check, or a refusal or look-ahead kept may be stale.
     */
    fun changed(client: String) = versions.changed(client)

    // Whether [client], refused [keys], may have them since its next step turns back in a free dead-end bay (a retreat's
    // park bay, a station stub): on the bay's mouth it needs only the bay, which no other vehicle can reach past it, so
    // it is judged as it will stand in the bay, by the bay's way out ([behindInBay]: what its length covers there).
    // The vehicles looked at are added to [witnesses] (developer's guide, 12, "Session 32").
    private fun maySafelyStopInBay(
        client: String,
        keys: Set<String>,
        behindInBay: (bay: Set<String>) -> Set<String>,
        witnesses: MutableSet<String>,
    ): Boolean {
        val route = routes[client] ?: return false
        val index = claimedStep(client, keys).takeIf { it >= 0 } ?: return false
        val bay = route.getOrNull(index + 1)?.takeIf { it.intoDeadEnd && route.getOrNull(index + 2)?.twoWay != false }
        val stop = bay?.stop ?: return false
        val occupants = bay.physical.flatMapTo(HashSet()) { holders(it) }
        witnesses += occupants
        if (occupants.any { it != client }) return false
        val walk = walk(client, keysHeldAfter(bay.keys, behindInBay(bay.physical)))
        return !walk.isBlocked(LookAhead(stop.required, stop.options), client).also { witnesses += walk.reached() }
    }

    // [pinned]: a vehicle that stays where it stands, whatever it needs.
    private fun isSafe(client: String, keys: Set<String>, behind: Set<String>, pinned: String? = null): Boolean {
        val held = keysHeldAfter(keys, behind)
        return !walk(client, held, pinned).isBlocked(lookAhead(client, keys, held), client)
    }

    /**
     * Who holds what [client] would need next after a grant of [keys]: whom a held-back grant waits for. The ways on
     * count only when every one of them is held, as in the check itself: one free way on is a way out.
     */
    fun blockersAfter(client: String, keys: Set<String>, behind: Set<String>): Map<String, Set<String>> {
        val ahead = lookAhead(client, keys, keysHeldAfter(keys, behind))
        val blockers = HashMap<String, MutableSet<String>>()
        fun note(key: String) = holders(key).filter { it != client }.forEach { blockers.getOrPut(it, ::HashSet) += key }
        ahead.required.forEach(::note)
        val noWayOn = ahead.options.all { option -> option.any { key -> holders(key).any { it != client } } }
        if (noWayOn) ahead.options.flatten().forEach(::note)
        return blockers
    }

    /** A step a vehicle asks for: its client, its keys and what its length covers behind it once there. */
    class Requester(val client: String, val keys: Set<String>, val behind: Set<String>)

    /**
     * Whether granting [keys] to [client] (which passed [mayGrant]) would leave a *dead hole*: a free point or path that
     * a vehicle in the grantee's way needs next and that another vehicle asking for it (`requesters`) could take now,
     * even if the grantee never moved, but that none of them (the grantee included, for its own next step) could take
     * once the grantee has driven there, since each would then wait, through a chain of waits, for itself.
     * Such a key stays free for good and every vehicle queued on it waits: the grids' two full squares that share
     * their last free corner (developer's guide, "The traffic rule"). Only one-way steps are looked at: on a two-way
     * stretch the look-ahead covers the whole stretch already. The check follows at most [MAX_AHEAD] vehicles ahead.
     * Only the vehicles that have asked count: two grants may then hold each other back, each for a hole the other
     * could take, until one of them is retried after a release or its patience ends (developer's guide, section 12).
     * A hole counts as taken only by a step that does not free, where the vehicle stood, a point every other vehicle
     * asking for it could then not take ([vacatesDeadHole]): the knot two moves on.
     */
    fun leavesDeadHole(client: String, keys: Set<String>, behind: Set<String>): Boolean {
        if (keys.any(exits::isTwoWay)) return false
        val held = keysHeldAfter(keys, behind)
        val granted = claimedStep(client, keys)
        val holes = assume(client, held, granted) { holesAhead(client) }
        if (holes.isEmpty()) return false
        val next = routes[client]?.withIndex()?.firstOrNull { it.index != granted }?.value
            ?.let { Requester(client, it.keys, emptySet()) }
        val safeBefore = HashMap<String, Boolean>()
        val safeAfter = HashMap<String, Boolean>()
        val dead = holes.any { hole ->
            val others = requesters(hole).filter { it.client != client }
            val asking = if (next != null && hole in next.keys) others + next else others
            others.none { it.keys.any(exits::isTwoWay) } &&
                others.any { safeBefore.getOrPut(it.client) { isSafeFor(it, pinned = client) } } &&
                asking.none { requester ->
                    safeAfter.getOrPut(requester.client) {
                        assume(client, held, granted) { isSafeFor(requester) && !vacatesDeadHole(requester) }
                    }
                }
        }
        if (dead) deadHolesHeldBack++
        return dead
    }

    private fun isSafeFor(requester: Requester, pinned: String? = null): Boolean =
        isSafe(requester.client, requester.keys, requester.behind, pinned)

    // Whether [requester]'s step would leave the point it stands on free for good (every other vehicle asking for it
    // would then wait, through a chain of waits, for itself): a hole only such a step fills is dead too (guide, 12).
    private fun vacatesDeadHole(requester: Requester): Boolean {
        val after = keysHeldAfter(requester.keys, requester.behind)
        val vacated = assumed.holdingsOf(requester.client).filter { it !in after && exits.isPoint(it) }
        if (vacated.isEmpty()) return false
        return assume(requester.client, after, claimedStep(requester.client, requester.keys)) {
            vacated.any { point ->
                val takers = requesters(point).filter { it.client != requester.client }
                takers.isNotEmpty() && takers.none { isSafeFor(it) }
            }
        }
    }

    // The free keys that [client] or a vehicle in its way, through the holders of what each needs, needs next. What
    // the grantee leaves behind is none: nobody could take it before the grant.
    private fun holesAhead(client: String): Set<String> {
        val holes = HashSet<String>()
        val seen = hashSetOf(client)
        val queue = ArrayDeque(listOf(client))
        while (queue.isNotEmpty() && seen.size <= MAX_AHEAD) {
            lookAhead(queue.removeFirst()).forEachKey { key ->
                val keyHolders = assumed.holdersOf(key)
                if (keyHolders.isEmpty() && holders(key).isEmpty()) holes += key
                for (holder in keyHolders) if (seen.add(holder)) queue += holder
            }
        }
        return holes
    }

    // Runs [body] as if [client] held [held] and its claimed step at index [granted] (if any) were granted.
    private fun <T> assume(client: String, held: Set<String>, granted: Int, body: () -> T): T {
        val route = routes[client]
        val step = if (granted >= 0) route?.removeAt(granted) else null
        try {
            return assumed.assuming(client, held, body)
        } finally {
            if (step != null) route?.add(granted, step)
        }
    }

    /** Whether [client], as it stands, waits through a chain of waits for itself (only a fresh claim can do that). */
    fun waitsForItself(client: String): Boolean = walk(client, holdings(client)).isBlocked(lookAhead(client), client)

    /** What [client], as it stands, needs next and vehicles waiting, through others, for it hold. */
    fun selfBlockers(client: String): Set<String> {
        val walk = walk(client, holdings(client))
        val ahead = lookAhead(client)
        if (!walk.isBlocked(ahead, client)) return emptySet()
        val blocked = HashSet<String>()
        ahead.forEachKey { if (walk.isTaken(it, client)) blocked += it }
        return blocked
    }

    /**
     * Whether [client] would wait through a chain of waits for itself if it claimed [route] instead of what it claims
     * now (arguments as for [claim]), or would be held back for good at its first step ([behindFirst]: what its length
     * covers once there; [behindInBay] as for [mayGrant]), which the next grant's check would refuse; its claim stays
     * as it is.
     */
    fun wouldWaitForItself(
        client: String,
        route: List<Set<String>>,
        stops: List<String?>,
        end: String?,
        behindFirst: Set<String>,
        behindInBay: (bay: Set<String>) -> Set<String> = { behindFirst + physicalOf(route.firstOrNull().orEmpty()) },
    ): Boolean {
        val oldRoute = routes[client]
        val oldWayOut = wayOut[client]
        claim(client, route, stops, end)
        try {
            val first = route.firstOrNull() ?: return waitsForItself(client)
            return waitsForItself(client) ||
                (!isSafe(client, first, behindFirst) && !maySafelyStopInBay(client, first, behindInBay, HashSet()))
        } finally {
            if (oldRoute == null) routes.remove(client) else routes[client] = oldRoute
            if (oldWayOut == null) wayOut.remove(client) else wayOut[client] = oldWayOut
            changed(client)
        }
    }

    /**
     * The dead-end stop (a station stub) [client]'s claim comes to right after the step with [keys], with every step
     * between them inside [corridor] (its member points and paths); null if its next stop is elsewhere or that step
     * itself ends at a stop.
     */
    fun deadEndStopInside(client: String, keys: Set<String>, corridor: Set<String>): String? {
        val route = routes[client] ?: return null
        val from = claimedStep(client, keys).takeIf { it >= 0 } ?: return null
        // A step into a stop of its own (an operation there first) is judged when the vehicle comes back out.
        if (route[from].stop != null) return null
        for (index in from + 1 until route.size) {
            val step = route[index]
            if (step.stop != null) return if (step.intoDeadEnd) pointOf(step.physical) else null
            if (step.physical.none(corridor::contains)) return null
        }
        return null
    }

    /** What [client] needs next as deadlock avoidance sees it, for diagnostics. */
    fun needs(client: String): Set<String> {
        val needs = HashSet<String>()
        lookAhead(client).forEachKey(needs::add)
        return needs
    }

    private fun walk(grantee: String, held: Set<String>, pinned: String? = null) =
        ReachabilityWalk(grantee, held, pinned, assumed) { lookAhead(it) }

    // [client]'s look-ahead as it stands, kept until it changes (a grant looked at as if made is not kept).
    private fun lookAhead(client: String): LookAhead {
        if (client in assumed) return lookAhead(client, null, assumed.holdingsOf(client))
        val version = versions.of(client)
        lookAheads[client]?.takeIf { it.version == version }?.let { return it.ahead }
        return lookAhead(client, null, holdings(client)).also { lookAheads[client] = KnownLookAhead(version, it) }
    }

    // The next step, every following step while on a two-way stretch or inside what the client holds anyway (a
    // SINGLE_VEHICLE_ONLY block it is in: its real next need is the first step out of it), and the way out at the end
    // of the claim. A stop for an operation on the way ends the look-ahead with the way out of that stop: a vehicle
    // standing there waits for nothing else. A grantee ([skipping] its grant) is looked at as it will be: holding
    // [holding]; a grant into a dead-end bay it leaves over a two-way path (a station stub or park bay beside an aisle)
    // is judged by the way out of the bay, as any other stop: the way on after it is judged when it asks to come out,
    // once the vehicles it let pass have gone. Stops left over one-way lanes keep the way on (the grids' stations).
    // A one-way step ends the look-ahead, unless the step after it goes into a dead-end stop: that one counts too.
    private fun lookAhead(client: String, skipping: Set<String>?, holding: Set<String>): LookAhead {
        val exit = wayOut[client] ?: Exit.NONE
        val route = routes[client] ?: return LookAhead(exit.required, exit.options)
        val ahead = HashSet<String>()
        val skippingPhysical = skipping?.let(::physicalOf)
        var skipped = skipping == null
        for ((i, step) in route.withIndex()) {
            if (!skipped && step.physical == skippingPhysical) {
                skipped = true
                val stop = step.stop
                if (stop != null && route.getOrNull(i + 1)?.twoWay == true) {
                    return LookAhead(ahead + stop.required, stop.options)
                }
                continue
            }
            ahead += step.keys
            val holdsAll = holding.containsAll(step.physical)
            // An operation where the client stands: what it waits for next is the step after it, not any way out.
            if (!holdsAll && step.physical.all { it in holding || exits.isLocation(it) }) continue
            if (!step.twoWay && !holdsAll) {
                // Waiting on a dead-end stub's mouth to come in, it would stand in the way out of whoever is inside.
                route.getOrNull(i + 1)?.takeIf { it.intoDeadEnd }?.let { ahead += it.keys }
                return LookAhead(ahead, emptyList())
            }
            step.stop?.let { return LookAhead(ahead + it.required, it.options) }
        }
        ahead += exit.required
        return LookAhead(ahead, exit.options)
    }
}

private const val MAX_AHEAD = 64
