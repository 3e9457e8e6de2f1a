package org.ktcs.kernel.scheduling

/**
 * Who waits for whom: for each waiting client, the clients standing in its way, each with the resources involved
 * (a scheduler's [org.ktcs.api.scheduling.Scheduler.waitsFor]). Its size is that of the waiting clients, not of the
 * plant model.
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
