package org.ktcs.kernel.scheduling

import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.Block
import org.ktcs.api.model.PlantModel
import org.ktcs.api.scheduling.Retreat
import org.ktcs.api.scheduling.Scheduler
import org.ktcs.api.scheduling.SchedulerClient
import org.ktcs.kernel.scheduling.TrafficTimers.DEAD_HOLE_PATIENCE_MILLIS
import org.ktcs.kernel.scheduling.TrafficTimers.HELD_BACK_REPORT_MILLIS
import org.ktcs.kernel.scheduling.TrafficTimers.PARK_TEST_PATIENCE_MILLIS
import org.slf4j.LoggerFactory
import java.util.TreeSet

/**
 * The default [Scheduler]: exclusive points, paths and locations, SINGLE_VEHICLE_ONLY and SAME_DIRECTION_ONLY blocks
 * (see [BLOCK_ENTRY_DIRECTION]), the implicit same-direction records of the plant's two-way corridors ([Corridors])
 * and paused clients.
 *
 * Confined to the kernel context. A grant is decided at once, and its resources count as held from then on; the
 * client hears of it through [KernelClock.schedule]. A request touching a SINGLE_VEHICLE_ONLY block holds the whole
 * block until the client has given back every member it asked for; [allocations] shows those extra members,
 * [SchedulerClient.onAllocationGranted] and [pendingAllocations] only what was asked for.
 *
 * Fairness: each client's requests are granted in its own order. A release re-checks only the requests waiting for
 * what it released, oldest first; a request needing several resources may still be overtaken by younger ones that
 * need part of them, so, as in openTCS, starvation is possible.
 */
class DefaultScheduler(model: PlantModel, private val clock: KernelClock) : Scheduler {
    private var blocks = BlockIndex(model)
    private var corridors = Corridors(model)
    private var occupancy = Occupancy(blocks, corridors)
    private var corridorSteps = newCorridorSteps()
    private var pending = PendingRequests()
    private var deliveries = Deliveries(clock)
    private var safety = newSafety(model)
    private var parks = newParkGuard(model)
    private val held = HeldBackRequests()
    private val claims = LinkedHashMap<String, List<Set<String>>>()
    private val lastGrants = HashMap<String, Request>()
    private val paused = HashSet<String>()

    private var releases = 0L
    private var nextSeq = 0L

    override val grantsHeldBack: Long get() = safety.heldBack + parks.heldBack + deadHolesAvoided

    /** Grants held back because they would have left a free point that nobody asking for it could take. */
    val deadHolesAvoided: Long get() = safety.deadHolesHeldBack

    /** Grants the park test had held back that its patience then left to the local rule alone. */
    var grantsAfterPatience = 0L
        private set

    override fun updatePlantModel(model: PlantModel) {
        deliveries.cancelAll()
        blocks = BlockIndex(model)
        corridors = Corridors(model)
        occupancy = Occupancy(blocks, corridors)
        corridorSteps = newCorridorSteps()
        pending = PendingRequests()
        deliveries = Deliveries(clock)
        safety = newSafety(model)
        parks = newParkGuard(model)
        held.clear()
        lastGrants.clear()
        claims.clear()
        paused.clear()
    }

    override fun claim(client: SchedulerClient, resources: List<Set<String>>) {
        claims[client.name] = resources.map { it.toSet() }
        safety.claim(
            client.name,
            routeKeys(client.name, resources),
            safety.stopsOf(resources),
            resources.lastOrNull()?.let(safety::pointOf),
        )
        retryDeferred()
    }

    override fun unclaim(client: SchedulerClient) {
        claims.remove(client.name)
        safety.unclaim(client.name)
        // Without a route it is bound into no corridor: standing at a corridor's end, it keeps nobody out any more.
        val left = occupancy.leaveGates(client.name)
        safety.changed(client.name)
        wake(left)
        retryDeferred()
    }

    /** The route ahead that each client claimed, by client name; claims never block anybody. */
    fun claims(): Map<String, List<Set<String>>> = claims.toMap()

    override fun allocate(client: SchedulerClient, resources: Set<String>) {
        val request = newRequest(client, resources)
        if (pending.add(request)) process(listOf(request))
    }

    override fun allocateNow(client: SchedulerClient, resources: Set<String>) {
        val request = newRequest(client, resources)
        for ((resource, others) in occupancy.collisions(client.name, request)) {
            log.warn("Vehicle {} takes {} although vehicle(s) {} hold it", client.name, resource, others.sorted())
        }
        val taken = occupancy.take(client.name, request)
        lastGrants.remove(client.name)
        safety.standing(client.name)
        parks.changed(client.name)
        process(pending.waitingFor(taken.redirected) + listOfNotNull(pending.head(client.name)))
        retryDeferred()
    }

    // A grant already decided is still announced: the client refuses it if it no longer wants it.
    override fun clearPendingAllocations(client: SchedulerClient) {
        pending.clear(client.name)
    }

    override fun free(client: SchedulerClient, resources: Set<String>) {
        val released = occupancy.release(client.name, resources - deliveries.withhold(client.name, resources))
        if (released.isNotEmpty()) releases++
        safety.standing(client.name)
        parks.changed(client.name)
        wake(released)
        retryDeferred()
    }

    override fun freeAll(client: SchedulerClient) {
        deliveries.cancel(client.name)
        pending.clear(client.name)
        claims.remove(client.name)
        lastGrants.remove(client.name)
        safety.remove(client.name)
        releases++
        val released = occupancy.releaseAll(client.name)
        safety.changed(client.name)
        parks.changed(client.name)
        wake(released)
        retryDeferred()
    }

    override fun setPaused(client: SchedulerClient, paused: Boolean) {
        if (paused) {
            this.paused += client.name
        } else if (this.paused.remove(client.name)) {
            process(listOfNotNull(pending.head(client.name)))
            retryDeferred()
        }
    }

    override fun allocations(): Map<String, Set<String>> = occupancy.snapshot()

    override fun allocationsOf(client: String): Set<String> = occupancy.heldBy(client)

    override fun pendingAllocations(): Map<String, List<Set<String>>> = pending.snapshot()

    /** The clients whose next grant deadlock avoidance holds back now (until something is freed that makes it safe). */
    fun heldBackClients(): Set<String> = held.all.mapTo(HashSet()) { it.client.name }

    /** The direction in which the users of each SAME_DIRECTION_ONLY block entered it, where known, by block name. */
    fun blockDirections(): Map<String, String> = occupancy.directions.directions()

    /** The way the vehicles in each two-way corridor in use head along it ([Corridors.UP] or [Corridors.DOWN]). */
    fun corridorDirections(): Map<String, String> = occupancy.corridorDirections.directions()

    /** The plant's two-way corridors, each as an implicit SAME_DIRECTION_ONLY block of its inner points and paths. */
    fun corridors(): List<Block> = corridors.blocks

    /**
     * Why [client]'s oldest pending request is not granted, and who holds what it needs (for [GrantWait.OCCUPIED]),
     * as `simulate` breaks the vehicles' held-back time down; [GrantWait.NONE_PENDING] when it asks for nothing.
     */
    fun grantWaitOf(client: String): Pair<GrantWait, Set<String>> {
        val request = pending.head(client) ?: return GrantWait.NONE_PENDING to emptySet()
        return when {
            client in paused -> GrantWait.PAUSED to emptySet()
            !occupancy.mayTake(client, request) -> GrantWait.OCCUPIED to occupancy.blockersOf(client, request).keys
            request in held -> (held.reason(request) ?: GrantWait.LOCAL_RULE) to emptySet()
            else -> GrantWait.NONE_PENDING to emptySet()
        }
    }

    /** [waitsFor] as a graph, for the deadlock detector. */
    fun waitForGraph(): WaitForGraph = WaitForGraph(waitsFor())

    /**
     * Whom each client's oldest pending request waits for, including the users of blocks it may not enter yet and,
     * for a grant deadlock avoidance holds back, the vehicles in its way. A client driving away from a resource it
     * was granted more ahead of does not count as blocking it: it gives the resource up as it drives.
     */
    override fun waitsFor(): Map<String, Map<String, Set<String>>> =
        pending.heads()
            .associate { request ->
                request.client.name to (occupancy.blockersOf(request.client.name, request) + heldBackBy(request))
                    .mapValues { (blocker, resources) -> stillBlocking(blocker, resources) }
                    .filterValues { it.isNotEmpty() }
            }
            .filterValues { it.isNotEmpty() }

    // A grant held back for longer than HELD_BACK_REPORT_MILLIS waits for whoever holds what it would need next: if
    // those wait for it in turn (vehicles meeting head-on on a two-way stretch), the watchdog sees a deadlock and
    // routes one of them around it, instead of both waiting for good.
    private fun heldBackBy(request: Request): Map<String, Set<String>> {
        val heldFor = held.heldFor(request, clock.elapsedMillis())
        if (heldFor < HELD_BACK_REPORT_MILLIS || request !in held) return emptyMap()
        if (held.reason(request) == GrantWait.STATION_TAKEN) stationTaken(request)?.let { return it }
        return safety.blockersAfter(request.client.name, request.keys, keysBehind(request.client, request.resources))
    }

    // Of what a client blocks, what it holds now but gives up as it drives on does not count.
    private fun stillBlocking(client: String, resources: Set<String>): Set<String> {
        val holds = occupancy.holdingKeys(client)
        val kept = keptBy(client)
        // A corridor's way in stays shut to the other way for as long as the client is inside, wherever it drives.
        return resources.filterTo(HashSet()) { it !in holds || it in kept || Corridors.isDirectionKey(it) }
    }

    // What a client will still hold once it has driven everything it was granted (everything, if it drives nothing).
    // A last grant the client no longer holds (it refused it, or gave it back) says nothing about where it goes.
    private fun keptBy(client: String): Set<String> {
        val last = heldLastGrant(client) ?: return occupancy.holdingKeys(client)
        return last.keys + keysBehind(last.client, last.resources)
    }

    // The client's last grant if it still holds it; a grant it refused or gave back says nothing about where it is.
    private fun heldLastGrant(client: String): Request? =
        lastGrants[client]?.takeIf { occupancy.holdingKeys(client).containsAll(it.physicalKeys) }

    /**
     * Whether [client]'s claim makes it wait, through others, for itself: its first step leads into vehicles that
     * wait for what it stands on. A claim cannot be refused, so the client should route around that step.
     */
    override fun claimIsBlocked(client: SchedulerClient): Boolean = safety.waitsForItself(client.name)

    override fun claimBlockers(client: SchedulerClient): Set<String> = safety.selfBlockers(client.name)

    /** The clients whose next request the local rule holds back for [client], whose own it holds back for them. */
    fun refusedMutually(client: String): Set<String> =
        localRuleBlockers(client).filterTo(HashSet()) { client in localRuleBlockers(it) }

    private fun localRuleBlockers(client: String): Set<String> {
        val request = pending.head(client)?.takeIf { it in held && held.reason(it) == GrantWait.LOCAL_RULE }
        return request?.let {
            safety.blockersAfter(client, it.keys, keysBehind(it.client, it.resources)).keys
        }.orEmpty()
    }

    /**
     * Whether [claimIsBlocked] would hold for [client] if it claimed [resources], or deadlock avoidance would hold back
     * its first step (a new route that leads into a cycle one step later breaks nothing); its claim stays as it is.
     */
    override fun claimWouldBeBlocked(client: SchedulerClient, resources: List<Set<String>>): Boolean =
        safety.wouldWaitForItself(
            client.name,
            routeKeys(client.name, resources),
            safety.stopsOf(resources),
            resources.lastOrNull()?.let(safety::pointOf),
            resources.firstOrNull()?.let { keysBehind(client, it) }.orEmpty(),
        ) { bay -> keysBehind(client, listOf(resources.first(), bay)) }

    /** What [client] still needs as deadlock avoidance sees it: its claimed route ahead and its way out. */
    fun needs(client: String): Set<String> = safety.needs(client)

    private fun newParkGuard(model: PlantModel) =
        ParkGuard(ParkSafety(model), { occupancy.clients() }, { occupancy.holdingKeys(it) }, ::frontOf) {
            blocks.singleBlocksOf(it).isNotEmpty()
        }

    // The point a client stands on or was granted last and still holds, if known.
    private fun frontOf(client: String): String? = heldLastGrant(client)?.let { safety.pointOf(it.resources) }
        ?: occupancy.holdingKeys(client).singleOrNull(safety::isPoint)

    /**
     * Those held back for longer than two watchdog periods, or [DEAD_END_RETREAT_MILLIS] for a retreat into a dead-end
     * bay; each retreat point is searched for when asked for.
     */
    override fun retreats(eligible: (String) -> Boolean): Sequence<Retreat> =
        parks.retreats(held.heldFor(clock.elapsedMillis()), eligible, ::claimEnds, safety::isDeadEnd)

    override fun retreatPoint(client: String): String? = parks.retreatPoint(client, claimEnds())

    // Where each claim ends, by point: a retreat into a bay where another vehicle's order ends (a park order's, say)
    // would meet that vehicle head-on at the bay's mouth.
    private fun claimEnds(): Map<String, String> =
        claims.entries.mapNotNull { (client, route) -> route.lastOrNull()?.let(safety::pointOf)?.to(client) }.toMap()

    /** Retries the grants held back for longer than the park test's patience, which the local rule alone decides now. */
    override fun retryOverdue() {
        val now = clock.elapsedMillis()
        if (held.all.any { held.heldFor(it, now) >= PARK_TEST_PATIENCE_MILLIS }) retryDeferred()
    }

    private fun newCorridorSteps() = CorridorSteps(corridors, occupancy.corridorDirections) { claims[it] }

    private fun newSafety(model: PlantModel) =
        RouteSafety(ExitCorridors(model), { occupancy.holdingKeys(it) }, { occupancy.holdersOf(it) }, ::requestersOf)

    // Per step of [client]'s route, its keys and, per corridor it comes into, the need key for the way it heads.
    private fun routeKeys(client: String, route: List<Set<String>>): List<Set<String>> =
        corridorSteps.routeKeys(client, route, blocks::keysOf)

    // What [client]'s length still covers behind it once it has driven [resources] (or all of [steps], none granted
    // yet), as deadlock avoidance counts it.
    private fun keysBehind(client: SchedulerClient, resources: Set<String>): Set<String> =
        blocks.keysOf(client.heldAfter(resources))

    private fun keysBehind(client: SchedulerClient, steps: List<Set<String>>): Set<String> =
        blocks.keysOf(client.heldAfter(steps))

    // Grants held back for safety may become safe after any change elsewhere; each retry costs one reachability walk.
    private fun retryDeferred() {
        if (held.isEmpty()) return
        process(held.takeAll())
        held.forgetSettled()
    }

    private fun newRequest(client: SchedulerClient, resources: Set<String>): Request =
        Request.of(nextSeq++, client, resources, blocks, corridorSteps)

    private fun wake(keys: Set<String>) {
        if (keys.isNotEmpty()) process(pending.waitingFor(keys))
    }

    // Granting never frees anything, so one pass in request order suffices; it only adds the next head of a served
    // client and the waiters of blocks whose direction changed.
    private fun process(candidates: Collection<Request>) {
        val queue = TreeSet(compareBy(Request::seq)).apply { addAll(candidates) }
        while (queue.isNotEmpty()) {
            val request = queue.pollFirst()!!
            if (!pending.isHead(request) || !isGrantable(request)) continue
            val behind = keysBehind(request.client, request.resources)
            val refusal = when {
                stationTaken(request) != null -> GrantWait.STATION_TAKEN
                !mayGrant(request, behind) -> GrantWait.LOCAL_RULE
                leavesDeadHole(request, behind) -> GrantWait.LOCAL_RULE
                !parkSafe(request, behind) -> GrantWait.PARK_TEST
                else -> null
            }
            if (refusal != null) {
                val heldFor = held.holdBack(request, refusal, clock.elapsedMillis())
                if (refusal != GrantWait.PARK_TEST && heldFor >= HELD_BACK_REPORT_MILLIS) queue += openStubGate(request)
                continue
            }
            held.granted(request)
            pending.pop(request.client.name)?.let(queue::add)
            queue += pending.waitingFor(grant(request))
        }
    }

    // Held back in a station stub for the report delay, a vehicle keeps nobody out of the corridor it leaves into: the
    // vehicles heading the other way pass the stub's mouth, or leave the stub it waits for, instead of waiting for it.
    private fun openStubGate(request: Request): Collection<Request> =
        occupancy.openGatesInStub(request.client.name, safety::isDeadEnd)
            .also { if (it.isNotEmpty()) safety.changed(request.client.name) }.let(pending::waitingFor)

    private fun mayGrant(request: Request, behind: Set<String>): Boolean =
        safety.mayGrant(request.client.name, request.keys, behind) {
            keysBehind(request.client, listOf(request.resources, it))
        }

    private fun stationTaken(request: Request) = occupancy.standingInStationAhead(request, safety)

    private fun leavesDeadHole(request: Request, behind: Set<String>): Boolean =
        held.heldFor(request, clock.elapsedMillis()) < DEAD_HOLE_PATIENCE_MILLIS &&
            safety.leavesDeadHole(request.client.name, request.keys, behind)

    // The first requests of the clients that ask for [key].
    private fun requestersOf(key: String): List<RouteSafety.Requester> =
        pending.waitingFor(setOf(key)).filter { pending.isHead(it) && key in it.keys }.map {
            RouteSafety.Requester(it.client.name, it.keys, keysBehind(it.client, it.resources))
        }

    // The park test is a preference, not a wall: a grant it has held back for PARK_TEST_PATIENCE_MILLIS is left to the
    // local rule alone (whose holds the watchdog sees), so a plant the test judges too pessimistically never freezes.
    private fun parkSafe(request: Request, behind: Set<String>): Boolean {
        if (held.heldFor(request, clock.elapsedMillis()) >= PARK_TEST_PATIENCE_MILLIS) {
            if (held.reason(request) == GrantWait.PARK_TEST) grantsAfterPatience++
            return true
        }
        if (held.parkRefusedAt[request.seq] == releases) return false
        if (parks.mayGrant(request.client.name, safety.pointOf(request.resources), request.keys + behind)) return true
        held.parkRefusedAt[request.seq] = releases
        return false
    }

    private fun isGrantable(request: Request): Boolean =
        request.client.name !in paused && occupancy.mayTake(request.client.name, request)

    private fun grant(request: Request): Set<String> {
        val taken = occupancy.take(request.client.name, request)
        safety.granted(request.client.name, request.keys)
        lastGrants[request.client.name] = request
        parks.changed(request.client.name)
        deliveries.send(request.client, request.resources) { withheld -> free(request.client, taken.added + withheld) }
        return taken.redirected
    }

    private companion object {
        private val log = LoggerFactory.getLogger(DefaultScheduler::class.java)
    }
}
