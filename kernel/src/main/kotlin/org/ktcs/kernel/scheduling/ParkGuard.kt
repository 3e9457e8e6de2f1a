package org.ktcs.kernel.scheduling

import org.ktcs.api.scheduling.Retreat
import org.ktcs.kernel.scheduling.TrafficTimers.DEAD_END_RETREAT_MILLIS
import org.ktcs.kernel.scheduling.TrafficTimers.HELD_BACK_REPORT_MILLIS
import org.slf4j.LoggerFactory

/**
 * Applies [ParkSafety] to the scheduler's state: a grant is made only if, once the grantee has driven there, every
 * vehicle could still get off the lanes into a park point; and a vehicle held back can be sent to retreat through a
 * free park point. Off (logged once) while the plant has fewer park points than vehicles holding something.
 *
 * The cost follows what changed, with the same answers as the test run on the whole fleet:
 * - each client's standing is kept until the scheduler reports a change of it ([changed]);
 * - once the fleet as it stands is known to be safe, a state that differs from it in a few vehicles is safe if those
 *   can be taken off first, one after the other ([ParkSafety.canLeave]: a search along their way out): without them
 *   the rest is a part of a safe fleet, and a part of a safe fleet is safe (fewer vehicles hold fewer points). Where
 *   one of them is shut in, a few unchanged vehicles standing in its way may be taken off before it (the rest is still
 *   a part of the safe fleet). Only when that fails does the test walk the plant;
 * - a refusal is kept with the vehicles that trapped each other ([ParkSafety.stuck]): it holds without a new test until
 *   one of them changes, since nothing the others do can free them.
 *
 * @param holdings what each client holds, as deadlock avoidance counts it.
 * @param front the point each client stands on or was granted last and still holds, if known.
 * @param inBlock whether a resource belongs to a SINGLE_VEHICLE_ONLY block (a vehicle in one may leave by any of its
 *   points).
 */
internal class ParkGuard(
    private val parks: ParkSafety,
    private val clients: () -> Set<String>,
    private val holdings: (String) -> Set<String>,
    private val front: (String) -> String?,
    private val inBlock: (String) -> Boolean,
) {
    private var warned = false
    private var changes = 0L

    // Per client standing on a point, its standing, and per client the count of changes when it last changed.
    private val standings = HashMap<String, Standing>()
    private val changedAt = HashMap<String, Long>()
    private val stale = LinkedHashSet<String>()
    private var allKnown = false

    // Per point, how many vehicles of the fleet as it stands hold it.
    private val holders = IntArray(parks.pointCount)

    // Whether the fleet was safe when [moved] was last cleared; [moved] names who changed since.
    private var knownSafe = true
    private val moved = LinkedHashSet<String>()

    private val refusals = HashMap<String, Refusal>()

    // Where the searches of vehicles that could not be taken off ran into others.
    private val blocked = IntStack()

    /** How many grants were held back because the state after them would not have been safe. */
    var heldBack = 0L
        private set

    /** Tells the guard that what [client] holds, or its front, has changed. */
    fun changed(client: String) {
        stale += client
        changedAt[client] = ++changes
    }

    /** Whether granting [client] the step ending at [point], after which it holds [heldAfter], keeps the state safe. */
    fun mayGrant(client: String, point: String?, heldAfter: Set<String>): Boolean {
        val at = point?.let(parks::pointIndex)?.takeIf { it >= 0 } ?: return true
        val grantee = standing(client, at, heldAfter)
        refresh()
        if (isOff(standings.size + if (client in standings) 0 else 1)) return true
        if (refusals[client]?.stillHolds(grantee) == true || !isSafe(grantee)) {
            heldBack++
            return false
        }
        refusals.remove(client)
        return true
    }

    /**
     * The nearest free park point [client] can drive to now over points nobody holds, or null; not one where another
     * client's claim ends ([claimEnds]: the client by point), which would meet it head-on at the bay's mouth.
     */
    fun retreatPoint(client: String, claimEnds: Map<String, String> = emptyMap()): String? {
        refresh()
        if (isOff(standings.size)) return null
        val fleet = standings.values.toList()
        return standings[client]?.let { standing ->
            parks.retreatPoint(fleet, standing) { point -> claimEnds[point].let { it != null && it != client } }
        }
    }

    /**
     * The clients held back ([heldFor]: for how long) for longer than two watchdog periods and [eligible], longest held
     * first, that can retreat now, each to its [retreatPoint]; into a dead-end bay only after [DEAD_END_RETREAT_MILLIS].
     */
    fun retreats(
        heldFor: Map<String, Long>,
        eligible: (String) -> Boolean,
        claimEnds: () -> Map<String, String>,
        isDeadEnd: (String) -> Boolean,
    ): Sequence<Retreat> {
        val ends by lazy(claimEnds)
        return heldFor.filterValues { it >= HELD_BACK_REPORT_MILLIS }.entries
            .sortedByDescending { it.value }
            .asSequence()
            .map { it.key }
            .filter(eligible)
            .mapNotNull { client -> retreatPoint(client, ends)?.let { Retreat(client, it) } }
            .filter { !isDeadEnd(it.parkPoint) || heldFor.getValue(it.vehicle) >= DEAD_END_RETREAT_MILLIS }
    }

    // Whether the fleet with [grantee] standing as after its grant is safe; a refusal is kept with its trap.
    private fun isSafe(grantee: Standing): Boolean {
        if (isSafeNow() && canLeaveInstead(grantee)) return true
        val fleet = ArrayList<Standing>(standings.size + 1)
        fleet += grantee
        for (standing in standings.values) if (standing.name != grantee.name) fleet += standing
        val stuck = parks.stuck(fleet)
        if (stuck.isEmpty()) return true
        val trap = stuck.filter { it.name != grantee.name }.map { it.name to version(it.name) }
        refusals[grantee.name] = Refusal(grantee, trap)
        return false
    }

    // Whether the fleet as it stands is safe: known, or its movers since it last was can leave first, or a full test.
    private fun isSafeNow(): Boolean {
        if (moved.isEmpty()) return knownSafe
        knownSafe = (knownSafe && canLeaveFirst(moved.mapNotNull(standings::get))) ||
            parks.isSafe(standings.values.toList())
        moved.clear()
        return knownSafe
    }

    // Whether [vehicles], all of the fleet as it stands, can be taken off one after the other before the others that
    // have not changed since the fleet was last known safe, helped by a few of those (see the class).
    private fun canLeaveFirst(vehicles: List<Standing>): Boolean = canTakeOff(vehicles)

    // Whether [grantee] could be taken off first (helped by a few others) if it stood so instead of as it stands.
    private fun canLeaveInstead(grantee: Standing): Boolean {
        val now = standings[grantee.name]
        now?.let { count(it, -1) }
        count(grantee, +1)
        val leaves = canTakeOff(listOf(grantee))
        count(grantee, -1)
        now?.let { count(it, +1) }
        return leaves
    }

    // Whether [targets] can be taken off one after the other, as [holders] counts the fleet, where at most HELPERS
    // tries take another vehicle off first that stands where a shut-in target's way out runs into it.
    private fun canTakeOff(targets: List<Standing>): Boolean {
        val names = targets.mapTo(HashSet()) { it.name }
        val left = ArrayList<Standing>(targets.size)
        var waiting = targets
        var tries = HELPERS
        try {
            while (waiting.isNotEmpty()) {
                blocked.clear()
                val leaving = waiting.filter { parks.canLeave(it, holders, blocked) }
                if (leaving.isNotEmpty()) {
                    leaving.forEach { count(it, -1) }
                    left += leaving
                    waiting = waiting - leaving.toSet()
                    continue
                }
                val helper = inTheWay(names, left).firstOrNull { tries-- > 0 && parks.canLeave(it, holders) }
                    ?: return false
                count(helper, -1)
                left += helper
            }
            return true
        } finally {
            left.forEach { count(it, +1) }
        }
    }

    // The vehicles other than [targets] and those taken off already that hold a point in [blocked].
    private fun inTheWay(targets: Set<String>, left: List<Standing>): Sequence<Standing> {
        val points = HashSet<Int>()
        blocked.forEach { points += it }
        return standings.values.asSequence()
            .filter { it.name !in targets && it !in left && it.points.any(points::contains) }
    }

    private fun isOff(vehicles: Int): Boolean {
        if (vehicles <= parks.parkPoints) return false
        if (!warned) {
            warned = true
            log.info(
                "deadlock avoidance: {} vehicles but {} park points, so the park test is off and the local rule " +
                    "works alone",
                vehicles,
                parks.parkPoints,
            )
        }
        return true
    }

    // Brings the standings of the clients that changed since the last test up to date.
    private fun refresh() {
        if (!allKnown) {
            clients().forEach(::changed)
            allKnown = true
        }
        for (client in stale) {
            standings.remove(client)?.let { count(it, -1) }
            val holds = holdings(client)
            val at = front(client)?.let(parks::pointIndex)?.takeIf { it >= 0 }
                ?: holds.firstNotNullOfOrNull { parks.pointIndex(it).takeIf { i -> i >= 0 } }
            if (at == null) {
                if (holds.isEmpty()) changedAt.remove(client)
                continue
            }
            val standing = standing(client, at, holds)
            standings[client] = standing
            count(standing, +1)
            moved += client
        }
        stale.clear()
    }

    private fun count(standing: Standing, by: Int) {
        for (point in standing.points) holders[point] += by
    }

    private fun version(client: String): Long = changedAt[client] ?: 0L

    private fun standing(client: String, at: Int, holds: Set<String>): Standing {
        if (holds.none(inBlock)) return Standing(client, at, indices(holds), intArrayOf(at))
        val exits = holds.filter(inBlock).map(parks::pointIndex).filter { it >= 0 && it != at }
        return Standing(client, at, indices(holds), (exits + at).toIntArray())
    }

    // The points among [keys], as indices.
    private fun indices(keys: Set<String>): IntArray {
        val points = IntArray(keys.size)
        var count = 0
        for (key in keys) {
            val point = parks.pointIndex(key)
            if (point >= 0) points[count++] = point
        }
        return if (count == points.size) points else points.copyOf(count)
    }

    // A refused grant and the other vehicles that trapped it, each with its version then.
    private inner class Refusal(val grantee: Standing, val trap: List<Pair<String, Long>>) {
        fun stillHolds(now: Standing): Boolean = now.sameAs(grantee) && trap.all { (name, at) -> version(name) == at }
    }

    private companion object {
        // How many vehicles in the way a cheap test tries to take off first before the test walks the plant.
        private const val HELPERS = 8
        private val log = LoggerFactory.getLogger(ParkGuard::class.java)
    }
}

private typealias Standing = ParkSafety.Standing
