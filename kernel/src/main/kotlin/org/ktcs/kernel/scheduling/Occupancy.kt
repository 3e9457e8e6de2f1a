package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block

/**
 * Who holds which resource. A client holds what it requested plus the rest of every SINGLE_VEHICLE_ONLY block it
 * requested a member of, and keeps such a block as long as it holds a requested member of it.
 *
 * Resource and block names double as wake-up keys: the release functions return the keys whose change may let a
 * waiting request through (block names are unique among all model objects, so they never clash with resources).
 */
internal class Occupancy(private val blocks: BlockIndex, private val corridors: Corridors) {
    private val holders = HashMap<String, MutableSet<String>>()
    private val held = HashMap<String, MutableSet<String>>()
    private val requested = HashMap<String, MutableSet<String>>()
    val directions = DirectionRecords()
    val corridorDirections = DirectionRecords()

    // Per client, per corridor it was let in at the end of (a gate), what it holds there: while it holds any of it, it
    // counts as a user of the corridor heading in, so nobody drives into the corridor towards it meanwhile.
    private val gates = HashMap<String, MutableMap<String, Gate>>()

    /**
     * What [client] holds as deadlock avoidance counts it: its resources, the SAME_DIRECTION_ONLY blocks it uses and,
     * per corridor it drives along, the way in for vehicles heading the other way ([Corridors.heldKeys]).
     */
    fun holdingKeys(client: String): Set<String> {
        val mine = held[client] ?: return emptySet()
        val used = mine.flatMap { blocks.sameDirectionBlocksOf(it) }
        val along = if (corridors.isEmpty) {
            emptySet()
        } else {
            mine.mapNotNullTo(HashSet()) { corridors.blockOf(it)?.name } + gates[client]?.keys.orEmpty()
        }
        if (used.isEmpty() && along.isEmpty()) return mine
        return mine + used.map { it.name } +
            along.flatMap { Corridors.heldKeys(it, corridorDirections.direction(it)) }
    }

    /** Who holds [key]: a resource, the name of a SAME_DIRECTION_ONLY block or a corridor's need key. */
    fun holdersOf(key: String): Collection<String> {
        holders[key]?.let { return it }
        if (!Corridors.isDirectionKey(key)) return directions.users(key)
        val block = Corridors.blockOfKey(key)
        val direction = corridorDirections.direction(block)
        val heading = Corridors.directionOfKey(key)
        return if (heading == null || direction == null || direction != heading) {
            corridorDirections.users(block)
        } else {
            emptySet()
        }
    }

    /** The clients holding anything. */
    fun clients(): Set<String> = held.keys

    fun snapshot(): Map<String, Set<String>> = held.mapValues { it.value.toSet() }

    /** What [client] holds, as a copy. */
    fun heldBy(client: String): Set<String> = held[client]?.toSet().orEmpty()

    /** Whether [client] holds a resource that passes [test], without copying what it holds. */
    fun holdsAny(client: String, test: (String) -> Boolean): Boolean = held[client]?.any(test) == true

    fun mayTake(client: String, request: Request): Boolean =
        request.expanded.all { isAvailable(it, client) } &&
            request.entries.all { directions.admits(it, client) } &&
            request.corridors.all { corridorDirections.admitsHeading(it, client) } &&
            request.gates.all { corridorDirections.admitsHeading(it, client) }

    /** The other clients standing in the way of [request], with the resources they block. */
    fun blockersOf(client: String, request: Request): Map<String, Set<String>> {
        val blockers = HashMap<String, MutableSet<String>>()
        for (resource in request.expanded) {
            othersHolding(resource, client).forEach { blockers.getOrPut(it, ::HashSet) += resource }
        }
        for (entry in request.entries.filterNot { directions.admits(it, client) }) {
            val others = directions.users(entry.block.name) - client
            others.forEach { blockers.getOrPut(it, ::HashSet) += entry.block.members }
        }
        for (entry in (request.corridors + request.gates).filterNot { corridorDirections.admitsHeading(it, client) }) {
            val others = corridorDirections.users(entry.block.name) - client
            for (other in others) {
                val gate = gates[other]?.get(entry.block.name)?.at.orEmpty()
                blockers.getOrPut(other, ::HashSet) +=
                    (entry.block.members + gate).filter { other in holders[it].orEmpty() }
            }
        }
        return blockers
    }

    /** The other clients holding what [request] asks for, by resource. */
    fun collisions(client: String, request: Request): Map<String, Set<String>> =
        request.expanded.associateWith { othersHolding(it, client) }.filterValues { it.isNotEmpty() }

    /** Gives [request] to [client], whoever holds it. */
    fun take(client: String, request: Request): Taken {
        val redirected = request.entries.filter { directions.enter(it, client) }.mapTo(HashSet()) { it.block.name }
        request.corridors.filter { corridorDirections.enter(it, client) }
            .forEach { redirected += Corridors.heldKeys(it.block.name, null) }
        for (gate in request.gates) {
            if (gates[client]?.containsKey(gate.block.name) == true) continue
            if (corridorDirections.enter(gate, client)) redirected += Corridors.heldKeys(gate.block.name, null)
            corridorDirections.memberTaken(gate.block, client)
            gates.getOrPut(client, ::HashMap)[gate.block.name] = Gate(gate.block, request.expanded)
        }
        val mine = requested.getOrPut(client, ::HashSet)
        val added = request.resources.filterTo(HashSet()) { mine.add(it) }
        request.expanded.forEach { hold(client, it) }
        return Taken(added, redirected)
    }

    /** Gives [resources] back, and the rest of each SINGLE_VEHICLE_ONLY block no longer justified. */
    fun release(client: String, resources: Set<String>): Set<String> {
        val mine = requested[client] ?: return emptySet()
        mine.removeAll(resources)
        val active = HashMap<String, Boolean>()
        val unjustified = blocks.expand(resources).filter { it !in mine && !isImplied(it, mine, active) }
        if (mine.isEmpty()) requested.remove(client)
        return unjustified.flatMapTo(HashSet()) { drop(client, it) }
    }

    fun releaseAll(client: String): Set<String> {
        requested.remove(client)
        return held[client].orEmpty().toList().flatMapTo(HashSet()) { drop(client, it) }
    }

    private fun isAvailable(resource: String, client: String): Boolean = holders[resource]?.all { it == client } ?: true

    private fun othersHolding(resource: String, client: String): Set<String> = holders[resource].orEmpty() - client

    private fun isImplied(resource: String, mine: Set<String>, active: MutableMap<String, Boolean>): Boolean =
        blocks.singleBlocksOf(resource).any { block ->
            active.getOrPut(block.name) { block.members.any { it in mine } }
        }

    private fun hold(client: String, resource: String) {
        if (!held.getOrPut(client, ::HashSet).add(resource)) return
        holders.getOrPut(resource, ::LinkedHashSet) += client
        blocks.sameDirectionBlocksOf(resource).forEach { directions.memberTaken(it, client) }
        corridors.blockOf(resource)?.let { corridorDirections.memberTaken(it, client) }
    }

    // Any holder leaving is a wake-up, not only the last: after allocateNow the remaining holder may be waiting.
    private fun drop(client: String, resource: String): List<String> {
        val mine = held[client] ?: return emptyList()
        if (!mine.remove(resource)) return emptyList()
        if (mine.isEmpty()) held.remove(client)
        val others = holders.getValue(resource).apply { remove(client) }
        if (others.isEmpty()) holders.remove(resource)
        val left = blocks.sameDirectionBlocksOf(resource).filter { directions.memberReleased(it, client) }
        val leftCorridor = corridors.blockOf(resource)?.takeIf { corridorDirections.memberReleased(it, client) }
        val corridorKeys = leftCorridor?.let { Corridors.heldKeys(it.name, null) }.orEmpty()
        return listOf(resource) + left.map { it.name } + corridorKeys + leaveGates(client, resource)
    }

    /** Drops every gate [client] holds (it is bound into no corridor any more); returns the keys that frees. */
    fun leaveGates(client: String): Set<String> {
        val mine = gates.remove(client) ?: return emptySet()
        return leave(client, mine.values).toSet()
    }

    // Drops the gates [client] no longer holds anything of once it gave back [resource]; returns the keys they free.
    private fun leaveGates(client: String, resource: String): List<String> {
        val mine = gates[client] ?: return emptyList()
        val mineHeld = held[client].orEmpty()
        val left = mine.values.filter { resource in it.at && it.at.none(mineHeld::contains) }
        if (left.isEmpty()) return emptyList()
        left.forEach { mine.remove(it.block.name) }
        if (mine.isEmpty()) gates.remove(client)
        return leave(client, left)
    }

    // [client] no longer counts as a user through [left]; returns the wake-up keys of the corridors it has now left.
    private fun leave(client: String, left: Collection<Gate>): List<String> {
        val emptied = left.filter { corridorDirections.memberReleased(it.block, client) }
        return emptied.flatMap { Corridors.heldKeys(it.block.name, null) }
    }
}

/** A corridor a client was let in at the end of ([Request.gates]), and what it holds there. */
private class Gate(val block: Block, val at: Set<String>)

/** What a grant changed: the resources newly requested, and the blocks whose direction changed. */
internal class Taken(val added: Set<String>, val redirected: Set<String>)
