package org.ktcs.kernel.scheduling

import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType

/**
 * The fleet-wide safety test of deadlock avoidance (developer's guide, "The traffic rule"): a state is *safe* if the
 * vehicles can be taken off the lanes one by one, each driving from its front (the point it stands on or was granted
 * last) over points free at that moment (the points of vehicles taken off before it count as free) into a park
 * point. A vehicle whose front is a park point, or a point from which no park point can be reached even on an empty
 * plant (the test has nothing to say about it), is taken off at once. Paths and locations are left out: a point is
 * free when nobody holds it. A park point is not used up by the vehicle that drives into it (the vehicle may drive on
 * from there, and counting each park point once cost far more than the grids' grants can afford: guide, section 12).
 *
 * One check grows the set of points that reach a free park point backwards from those park points, and a vehicle
 * taken off frees its points, which may join the set: a check costs the points and paths of the plant once, not a
 * search per vehicle. Built once per model; locks are ignored.
 */
internal class ParkSafety(model: PlantModel) {
    private val names: List<String> = model.points.map { it.name }
    private val index: Map<String, Int> = names.withIndex().associate { (i, name) -> name to i }
    private val isPark = BooleanArray(names.size) { model.points[it].type == PointType.PARK_POSITION }
    private val successors: Array<IntArray>
    private val predecessors: Array<IntArray>

    private val parkList: IntArray = names.indices.filter { isPark[it] }.toIntArray()

    /** How many park points the plant has: with fewer than there are vehicles the test cannot hold. */
    val parkPoints: Int = parkList.size

    init {
        val next = Array(names.size) { ArrayList<Int>() }
        val previous = Array(names.size) { ArrayList<Int>() }
        fun edge(from: String, to: String) {
            val a = index[from] ?: return
            val b = index[to] ?: return
            next[a] += b
            previous[b] += a
        }
        for (path in model.paths) {
            if (path.maxVelocity > 0) edge(path.sourcePoint, path.destinationPoint)
            if (path.maxReverseVelocity > 0) edge(path.destinationPoint, path.sourcePoint)
        }
        successors = Array(names.size) { next[it].toIntArray() }
        predecessors = Array(names.size) { previous[it].toIntArray() }
    }

    // Per point, how many paths it is from the nearest park point on the empty plant (MAX_VALUE: none can be reached).
    private val parkDistance = IntArray(names.size) { Int.MAX_VALUE }.also { distance ->
        val queue = IntQueue()
        for (point in parkList) {
            distance[point] = 0
            queue.push(point)
        }
        while (queue.isNotEmpty()) {
            val point = queue.take()
            for (previous in predecessors[point]) {
                if (distance[previous] != Int.MAX_VALUE) continue
                distance[previous] = distance[point] + 1
                queue.push(previous)
            }
        }
    }

    // Per point, its successors nearest a park point first.
    private val towardPark = Array(names.size) { point -> successors[point].sortedBy { parkDistance[it] }.toIntArray() }

    // Whether a park point can be reached from [point] on an empty plant.
    private fun canPark(point: Int): Boolean = parkDistance[point] != Int.MAX_VALUE

    private val buffers by lazy { Buffers() }

    /** How many points the plant has: the size of the per-point counts [canLeave] takes. */
    val pointCount: Int = names.size

    /** The index of point [name], or -1 if it is none. */
    fun pointIndex(name: String): Int = index[name] ?: -1

    /**
     * Whether every vehicle of [fleet] can be taken off the lanes (see the class). [fleet] lists each vehicle's front
     * and the points it holds, as indices ([pointIndex]).
     */
    fun isSafe(fleet: List<Standing>): Boolean = stuck(fleet).isEmpty()

    /**
     * The vehicles of [fleet] that cannot be taken off the lanes (none if the state is safe). They trap each other:
     * with only them holding anything none of them could leave, so the state stays unsafe whatever the others do
     * until one of them changes.
     */
    fun stuck(fleet: List<Standing>): List<Standing> {
        val removed = Check(fleet).removeAll()
        return fleet.filterIndexed { i, _ -> !removed[i] }
    }

    /**
     * Whether [vehicle] could be taken off the lanes first, while [holders] counts per point the vehicles holding it
     * (including [vehicle]): it is on a park point or where none can be reached, or one of its exits leads to a point
     * from which a way over free points ends in a free park point. A search nearest-to-a-park-point first, so on free
     * lanes it costs the way out, not the plant. If it cannot, [blocked] (when given) gets the held points where the
     * search ran into other vehicles.
     */
    fun canLeave(vehicle: Standing, holders: IntArray, blocked: IntStack? = null): Boolean {
        if (isPark[vehicle.front] || !canPark(vehicle.front)) return true
        val search = buffers.search
        val seen = buffers.seen
        val mark = ++buffers.searches
        for (exit in vehicle.exits) {
            for (start in towardPark[exit]) {
                if (holders[start] > 0) blocked?.push(start)
                if (holders[start] > 0 || seen[start] == mark) continue
                seen[start] = mark
                search.push(start)
            }
        }
        while (search.isNotEmpty()) {
            val point = search.pop()
            if (isPark[point]) return true.also { search.clear() }
            val next = towardPark[point]
            for (i in next.indices.reversed()) {
                val candidate = next[i]
                if (holders[candidate] > 0) blocked?.push(candidate)
                if (holders[candidate] > 0 || seen[candidate] == mark) continue
                seen[candidate] = mark
                search.push(candidate)
            }
        }
        return false
    }

    /**
     * The nearest free park point [vehicle] of [fleet] reaches from its front over points nobody holds, or null: where
     * it can retreat to now. Park points [taken] by another vehicle's claim are passed over.
     */
    fun retreatPoint(fleet: List<Standing>, vehicle: Standing, taken: (String) -> Boolean = { false }): String? {
        val held = BooleanArray(names.size)
        for (standing in fleet) standing.points.forEach { held[it] = true }
        val seen = BooleanArray(names.size)
        val queue = IntQueue()
        seen[vehicle.front] = true
        queue.push(vehicle.front)
        while (queue.isNotEmpty()) {
            for (next in successors[queue.take()]) {
                if (seen[next] || held[next]) continue
                if (isPark[next] && !taken(names[next])) return names[next]
                seen[next] = true
                queue.push(next)
            }
        }
        return null
    }

    /**
     * One vehicle as the test sees it: its [front], the [points] it holds and the points it can drive off from
     * ([exits]: its front and, inside a single-vehicle block, the block's points it holds), as indices.
     */
    class Standing(val name: String, val front: Int, val points: IntArray, val exits: IntArray = intArrayOf(front)) {
        /** Whether [other] is the same vehicle standing the same way. */
        fun sameAs(other: Standing): Boolean =
            name == other.name && front == other.front && points.contentEquals(other.points) &&
                exits.contentEquals(other.exits)
    }

    /**
     * One run of the test; see [removeAll]. Its arrays are reused from run to run (the scheduler is confined to the
     * kernel context); a run clears what it touched.
     */
    private inner class Check(private val fleet: List<Standing>) {
        private val holders = buffers.holders
        private val reaches = buffers.reaches
        private val frontHead = buffers.frontHead

        // Per point, the vehicles that can leave from it (linked through the nodes: vehicle index, next node).
        private val nodeVehicle = IntArray(fleet.sumOf { it.exits.size })
        private val nodeNext = IntArray(nodeVehicle.size)
        private val removed = BooleanArray(fleet.size)
        private val candidates = IntStack()

        // First in, first out: each point joins once, and a check walks the plant once.
        private val grow = IntQueue()
        private val touched = IntStack()

        /** Takes vehicles off as long as one can be; returns, per vehicle of the fleet, whether it was. */
        fun removeAll(): BooleanArray = try {
            run()
            removed
        } finally {
            touched.forEach { point ->
                holders[point] = 0
                reaches[point] = false
                frontHead[point] = -1
            }
        }

        private fun run() {
            var nodes = 0
            fleet.forEachIndexed { i, vehicle ->
                vehicle.points.forEach { point ->
                    holders[point]++
                    touched.push(point)
                }
                vehicle.exits.forEach { point ->
                    nodeVehicle[nodes] = i
                    nodeNext[nodes] = frontHead[point]
                    frontHead[point] = nodes++
                    touched.push(point)
                }
                if (isPark[vehicle.front] || !canPark(vehicle.front)) candidates.push(i)
            }
            for (point in parkList) if (holders[point] == 0) join(point)
            spread()
            while (candidates.isNotEmpty()) {
                val i = candidates.pop()
                if (removed[i]) continue
                removed[i] = true
                free(fleet[i])
                spread()
            }
        }

        private fun free(vehicle: Standing) {
            for (point in vehicle.points) {
                holders[point]--
                if (holders[point] > 0 || reaches[point]) continue
                if (isPark[point] || successors[point].any { reaches[it] }) join(point)
            }
        }

        private fun join(point: Int) {
            reaches[point] = true
            touched.push(point)
            grow.push(point)
        }

        // Backwards from every point that joined: free predecessors join, vehicles standing on them can leave.
        private fun spread() {
            while (grow.isNotEmpty()) {
                val point = grow.take()
                for (previous in predecessors[point]) {
                    var node = frontHead[previous]
                    while (node >= 0) {
                        if (!removed[nodeVehicle[node]]) candidates.push(nodeVehicle[node])
                        node = nodeNext[node]
                    }
                    if (!reaches[previous] && holders[previous] == 0) join(previous)
                }
            }
        }
    }

    /** Per-point arrays of [Check], kept clean between runs. */
    private inner class Buffers {
        val holders = IntArray(names.size)
        val reaches = BooleanArray(names.size)
        val frontHead = IntArray(names.size) { -1 }

        // For [canLeave]: the points to search from, and per point the number of the last search that saw it.
        val search = IntStack()
        val seen = IntArray(names.size)
        var searches = 0
    }
}
