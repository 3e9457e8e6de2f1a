package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.PlantModel

/**
 * The two-way corridors of a plant: chains of at least [MIN_INNER_POINTS] points that vehicles may drive both ways,
 * each with exactly two ways on once dead-end stubs (station stubs, park bays) are set aside; a warehouse aisle is
 * one. Each corridor gets an implicit same-direction record, as if it were a SAME_DIRECTION_ONLY block of its inner
 * points and paths: while a vehicle drives along it towards one end, no vehicle may enter it heading for the other.
 * Vehicles that met head-on inside, each with a queue behind it, could never get past each other, and no check of
 * the next step alone can undo that once both ends are admitted (see the developer's guide, "Traffic rule").
 *
 * A vehicle in a stub is not inside the corridor; coming out it heads wherever its route goes next. Built once per
 * model; locks are ignored, as a locked path may be unlocked while vehicles are inside.
 */
internal class Corridors(model: PlantModel) {
    private class Chain(val block: Block, val points: List<String>)

    private val pathEnds = model.paths.associate { it.name to (it.sourcePoint to it.destinationPoint) }
    private val chains: List<Chain> = findChains(model)
    private val chainOf = HashMap<String, Chain>().apply {
        for (chain in chains) chain.block.members.forEach { put(it, chain) }
    }
    private val indexOf = HashMap<Pair<Chain, String>, Int>().apply {
        for (chain in chains) chain.points.forEachIndexed { i, point -> put(chain to point, i) }
    }

    /** The corridor blocks, for diagnostics and tests. */
    val blocks: List<Block> get() = chains.map { it.block }

    /** Whether the plant has no corridor (a one-way grid): then no step needs looking at. */
    val isEmpty: Boolean = chains.isEmpty()

    /** The corridor [resource] is an inner point or path of, if any. */
    fun blockOf(resource: String): Block? = chainOf[resource]?.block

    /**
     * Per step of a route (resources in driving order), the corridors the step touches and the way the vehicle heads
     * along each: [UP] (towards the corridor's last point), [DOWN], or `null` if the route does not say (a step out of
     * a stub onto the corridor that is the route's last, or a vehicle placed on it). A step comes into a corridor
     * unless the step before it was in it already (for the first step: unless the vehicle is in it, [inside]).
     */
    fun entries(steps: List<Set<String>>, inside: (Block) -> Boolean): List<List<BlockEntry>> {
        var previous: Set<Chain> = emptySet()
        return steps.mapIndexed { i, step ->
            val touched = step.mapNotNullTo(LinkedHashSet()) { chainOf[it] }
            val entries = touched.map { chain ->
                val heading = heading(chain, step) ?: steps.getOrNull(i + 1)?.let { heading(chain, it) }
                // Out of a stub the vehicle comes in, even while it still covers the aisle point with its length.
                val entering = fromStub(chain, step) || if (i == 0) !inside(chain.block) else chain !in previous
                BlockEntry(chain.block, heading, entering)
            }
            previous = touched
            entries
        }
    }

    // A step onto a chain point by a path that is not the chain's: out of a stub beside it.
    private fun fromStub(chain: Chain, step: Set<String>): Boolean =
        step.any { it in pathEnds && chainOf[it] == null } && step.any { chainOf[it] === chain && it !in pathEnds }

    // The way a step drives along a chain: the chain path it uses and the point it ends at.
    private fun heading(chain: Chain, step: Set<String>): String? {
        val path = step.firstOrNull { chainOf[it] === chain && it in pathEnds } ?: return null
        val (source, destination) = pathEnds.getValue(path)
        val end = if (destination in step) {
            destination
        } else if (source in step) {
            source
        } else {
            return null
        }
        val from = if (end == destination) source else destination
        val to = indexOf[chain to end] ?: return null
        val back = indexOf[chain to from] ?: return null
        return if (to > back) UP else DOWN
    }

    companion object {
        /** A vehicle heading towards the corridor's last point. */
        const val UP = "up"

        /** A vehicle heading towards the corridor's first point. */
        const val DOWN = "down"

        /** Shorter two-way stretches are left to the deadlock check's look-ahead alone. */
        const val MIN_INNER_POINTS = 2

        private const val KEY_SEPARATOR = '\u0000'

        /** The key a step heading [direction] along [block] needs: nobody may use the corridor the other way. */
        fun needKey(block: String, direction: String?): String = "$block$KEY_SEPARATOR${direction ?: "?"}"

        /** Whether [key] is a corridor direction key rather than a resource or block name. */
        fun isDirectionKey(key: String): Boolean = KEY_SEPARATOR in key

        fun blockOfKey(key: String): String = key.substringBefore(KEY_SEPARATOR)

        fun directionOfKey(key: String): String? = key.substringAfter(KEY_SEPARATOR).takeIf { it != "?" }

        /**
         * The keys a user heading [direction] along [block] holds: the need keys of the other direction, and of an
         * unknown one; a user whose direction is unknown holds all of them.
         */
        fun heldKeys(block: String, direction: String?): List<String> =
            listOf(UP, DOWN, null).filter { direction == null || it != direction }.map { needKey(block, it) }

        private fun findChains(model: PlantModel): List<Chain> {
            val ways = HashMap<String, MutableSet<String>>()
            val pathsBetween = HashMap<Pair<String, String>, MutableList<String>>()
            for (path in model.paths) {
                val (a, b) = path.sourcePoint to path.destinationPoint
                if (a == b) continue
                if (path.maxVelocity > 0) ways.getOrPut(a, ::HashSet) += b
                if (path.maxReverseVelocity > 0) ways.getOrPut(b, ::HashSet) += a
                pathsBetween.getOrPut(minOf(a, b) to maxOf(a, b), ::ArrayList) += path.name
            }
            val neighbours = HashMap<String, MutableSet<String>>()
            for ((from, tos) in ways) {
                for (to in tos) {
                    neighbours.getOrPut(from, ::HashSet) += to
                    neighbours.getOrPut(to, ::HashSet) += from
                }
            }
            fun twoWay(a: String, b: String) = b in ways[a].orEmpty() && a in ways[b].orEmpty()
            fun isStub(p: String) = neighbours[p].orEmpty().singleOrNull()?.let { twoWay(p, it) } == true
            // Per point whose every connection is two-way, its neighbours other than stubs.
            val onward = neighbours.filter { (p, ns) -> ns.all { twoWay(p, it) } }
                .mapValues { it.value.filterNot(::isStub) }
            fun isInner(p: String) = !isStub(p) && onward[p]?.size == 2
            val seen = HashSet<String>()
            val chains = ArrayList<Chain>()
            for (start in model.points.map { it.name }.filter(::isInner)) {
                if (start in seen) continue
                val inner = walk(start, onward, ::isInner)
                seen += inner
                if (inner.size < MIN_INNER_POINTS) continue
                val ends = onward.getValue(inner.first()).filterNot { it in inner } +
                    onward.getValue(inner.last()).filterNot { it in inner }
                // A ring of corridor points has no ends to enter it by.
                if (ends.size != 2) continue
                val points = listOf(ends[0]) + inner + listOf(ends[1])
                val paths = points.zipWithNext()
                    .flatMap { (a, b) -> pathsBetween[minOf(a, b) to maxOf(a, b)].orEmpty() }
                // Named by its inner points, which belong to no other corridor: two may join the same ends.
                val name = "corridor ${inner.first()}..${inner.last()}"
                chains += Chain(Block(name, BlockType.SAME_DIRECTION_ONLY, (inner + paths).toSet()), points)
            }
            return chains
        }

        // The inner points of the chain through [start], in order from one end to the other.
        private fun walk(start: String, onward: Map<String, List<String>>, isInner: (String) -> Boolean): List<String> {
            fun extend(from: String, first: String): List<String> {
                val out = ArrayList<String>()
                var previous = from
                var current = first
                while (isInner(current) && current != start && out.size < onward.size) {
                    out += current
                    val next = onward.getValue(current).first { it != previous }
                    previous = current
                    current = next
                }
                return out
            }
            val (a, b) = onward.getValue(start)
            return extend(start, a).reversed() + start + extend(start, b)
        }
    }
}
