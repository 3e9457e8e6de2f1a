package org.ktcs.kernel.scheduling

/**
 * Who waits for whom: for each waiting client, the clients standing in its way, each with the resources involved.
 * Its size is that of the waiting clients, not of the plant model.
 */
class WaitForGraph(val edges: Map<String, Map<String, Set<String>>>) {
    /** The resources [waiter] wants and [holder] stands in the way with, or none if it does not wait for it. */
    fun contested(waiter: String, holder: String): Set<String> = edges[waiter]?.get(holder).orEmpty()

    /**
     * Every cycle found by a depth-first search, one per back edge, each listing the clients in waiting order (each
     * waits for the next, the last for the first). Every group of clients waiting for each other shows up in at
     * least one cycle; a densely entangled group is not broken down into all its cycles, whose number can grow
     * exponentially.
     */
    fun cycles(): List<List<String>> = CycleSearch(edges).run()

    companion object {
        /**
         * The graph of a scheduler's [allocations] and [pending] requests. A client waits for every holder of a
         * resource in its oldest pending request: its later requests cannot be granted before that one anyway.
         */
        fun of(allocations: Map<String, Set<String>>, pending: Map<String, List<Set<String>>>): WaitForGraph {
            val holders = HashMap<String, MutableSet<String>>()
            allocations.forEach { (client, resources) ->
                resources.forEach { holders.getOrPut(it, ::HashSet) += client }
            }
            val edges = pending.mapValues { (waiter, requests) -> blockers(waiter, requests.firstOrNull(), holders) }
            return WaitForGraph(edges.filterValues { it.isNotEmpty() })
        }

        private fun blockers(
            waiter: String,
            request: Set<String>?,
            holders: Map<String, Set<String>>,
        ): Map<String, Set<String>> {
            val blockers = HashMap<String, MutableSet<String>>()
            for (resource in request.orEmpty()) {
                for (holder in holders[resource].orEmpty() - waiter) {
                    blockers.getOrPut(holder, ::HashSet) += resource
                }
            }
            return blockers
        }
    }
}

private class CycleSearch(private val edges: Map<String, Map<String, Set<String>>>) {
    private val done = HashSet<String>()
    private val path = ArrayList<String>()
    private val onPath = HashSet<String>()
    private val cycles = ArrayList<List<String>>()

    fun run(): List<List<String>> {
        edges.keys.sorted().forEach { if (it !in done) visit(it) }
        return cycles
    }

    // Recursion depth is bounded by the number of waiting clients, a few hundred at most.
    private fun visit(node: String) {
        path += node
        onPath += node
        for (next in edges[node].orEmpty().keys.sorted()) {
            when (next) {
                in onPath -> cycles += path.subList(path.indexOf(next), path.size).toList()
                !in done -> visit(next)
            }
        }
        path.removeAt(path.lastIndex)
        onPath -= node
        done += node
    }
}
