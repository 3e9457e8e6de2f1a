package org.ktcs.kernel.routing

/**
 * The cheapest costs from every point to one point ([target]): Dijkstra's algorithm run backwards, along the edges into
 * each point, and only as far as the points asked about ([costsFrom]); a later question about a farther point resumes
 * it. One search answers how far each of many vehicles is from an order's first destination, where a search from each
 * vehicle would cost one search per vehicle. What it answered stays true: the graph never changes.
 */
internal class CostsToTree(private val graph: IndexedGraph, val target: Int) {
    val costs = LongArray(graph.size) { Long.MAX_VALUE }
    private var frontier: Frontier? = Frontier(graph.size)

    init {
        costs[target] = 0
        frontier?.offer(target, 0)
    }

    /** The costs of the cheapest route from [point] to [target], or `null` if there is none. */
    fun costsFrom(point: Int): Long? {
        val pending = frontier
        if (pending != null) {
            while (!pending.isSettled(point) && pending.isNotEmpty()) graph.settlePrevious(this, pending)
            if (!pending.isNotEmpty()) frontier = null
        }
        return costs[point].takeIf { it != Long.MAX_VALUE }
    }
}
