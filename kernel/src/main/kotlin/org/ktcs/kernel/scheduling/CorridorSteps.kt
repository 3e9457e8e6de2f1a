package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block

/**
 * The corridor entries ([Corridors]) of a client's steps, judged from the corridors it is in ([records]) and the
 * route it claimed ([claims]): which way a step heads along each corridor it touches, whether it comes into it, and
 * which corridor the route comes into right after it (a gate: the vehicle may take the corridor's end only once it
 * may come in).
 */
internal class CorridorSteps(
    private val corridors: Corridors,
    private val records: DirectionRecords,
    private val claims: (String) -> List<Set<String>>?,
) {
    /** Per step of [client]'s [route], [keysOf] the step plus, per corridor it comes into, the need key for its way. */
    fun routeKeys(client: String, route: List<Set<String>>, keysOf: (Set<String>) -> Set<String>): List<Set<String>> {
        if (corridors.isEmpty) return route.map(keysOf)
        return route.zip(corridors.entries(route) { isInside(client, it) }) { step, along ->
            val entering = along.filter { it.entering }
            if (entering.isEmpty()) {
                keysOf(step)
            } else {
                keysOf(step) + entering.map { Corridors.needKey(it.block.name, it.direction) }
            }
        }
    }

    /** The corridors [step] touches; a step out of a stub heads where the claimed route goes next. */
    fun entries(client: String, step: Set<String>): List<BlockEntry> {
        if (step.none { corridors.blockOf(it) != null }) return emptyList()
        val route = claims(client).orEmpty()
        val next = route.indexOfFirst { it == step }.takeIf { it >= 0 }?.let { route.getOrNull(it + 1) }
        return corridors.entries(listOfNotNull(step, next)) { isInside(client, it) }.first()
    }

    /**
     * The corridors the claimed route comes into right after [step]: the vehicle waits for the way in before it takes
     * the corridor's end, which the vehicles driving out of the corridor need.
     */
    fun gates(client: String, step: Set<String>): List<BlockEntry> {
        if (corridors.isEmpty) return emptyList()
        val route = claims(client) ?: return emptyList()
        val index = route.indexOfFirst { it == step }.takeIf { it >= 0 } ?: return emptyList()
        val next = route.getOrNull(index + 1) ?: return emptyList()
        if (next.none { corridors.blockOf(it) != null }) return emptyList()
        val ahead = listOfNotNull(step, next, route.getOrNull(index + 2))
        val entries = corridors.entries(ahead) { isInside(client, it) }
        val touched = entries[0].mapTo(HashSet()) { it.block.name }
        return entries[1].filter { it.entering && it.block.name !in touched && !isInside(client, it.block) }
    }

    private fun isInside(client: String, corridor: Block): Boolean = client in records.users(corridor.name)
}
