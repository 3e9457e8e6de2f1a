package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.PlantModel

/** The scheduler's rules, restated naively from the outside, to check a [DefaultScheduler] against. */
class SchedulingOracle(private val model: PlantModel) {
    private val singleBlocks = model.blocks.filter { it.type == BlockType.SINGLE_VEHICLE_ONLY }
    private val sameDirectionBlocks = model.blocks.filter { it.type == BlockType.SAME_DIRECTION_ONLY }

    fun sharedResources(allocations: Map<String, Set<String>>): List<String> = allocations.values
        .flatten()
        .groupingBy { it }
        .eachCount()
        .filterValues { it > 1 }
        .map { "resource ${it.key} held ${it.value} times" }

    fun sharedSingleBlocks(allocations: Map<String, Set<String>>): List<String> = singleBlocks
        .map { it to users(it, allocations) }
        .filter { (_, users) -> users.size > 1 }
        .map { (block, users) -> "block ${block.name} used by $users" }

    fun undirectedSharedBlocks(allocations: Map<String, Set<String>>, directions: Map<String, String>): List<String> =
        sameDirectionBlocks
            .filter { users(it, allocations).size > 1 && it.name !in directions }
            .map { "block ${it.name} shared without a direction" }

    /** Clients not holding exactly what they [kept], extended to whole SINGLE_VEHICLE_ONLY blocks. */
    fun unexpectedHoldings(allocations: Map<String, Set<String>>, kept: Map<String, Set<String>>): List<String> = kept
        .filter { (client, resources) -> allocations[client].orEmpty() != expand(resources) }
        .map { (client, resources) -> "$client holds ${allocations[client]}, expected ${expand(resources)}" }

    /** Clients whose oldest request waits although the scheduler could grant it. */
    fun lostWakeUps(
        allocations: Map<String, Set<String>>,
        pending: Map<String, List<Set<String>>>,
        directions: Map<String, String>,
        paused: Set<String>,
    ): List<String> = pending
        .filterKeys { it !in paused }
        .filter { (client, requests) -> isGrantable(client, requests.first(), allocations, directions) }
        .map { (client, requests) -> "$client waits for ${requests.first()} in vain" }

    private fun isGrantable(
        client: String,
        request: Set<String>,
        allocations: Map<String, Set<String>>,
        directions: Map<String, String>,
    ): Boolean {
        val expanded = expand(request)
        val others = allocations.filterKeys { it != client }.values.flatten().toSet()
        return expanded.none { it in others } &&
            sameDirectionBlocks.filter {
                it.touches(expanded)
            }.all { admits(it, client, expanded, allocations, directions) }
    }

    private fun admits(
        block: Block,
        client: String,
        request: Set<String>,
        allocations: Map<String, Set<String>>,
        directions: Map<String, String>,
    ): Boolean {
        val users = users(block, allocations)
        return users.isEmpty() || client in users ||
            entryDirection(block, request)?.let { it == directions[block.name] } == true
    }

    private fun entryDirection(block: Block, request: Set<String>): String? = request
        .mapNotNull { model.path(it) }
        .filter {
            it.sourcePoint !in block.members && (it.name in block.members || it.destinationPoint in block.members)
        }
        .map { it.properties[BLOCK_ENTRY_DIRECTION] ?: it.name }
        .minOrNull()

    private fun expand(resources: Set<String>): Set<String> =
        resources + singleBlocks.filter { it.touches(resources) }.flatMap { it.members }

    private fun users(block: Block, allocations: Map<String, Set<String>>): Set<String> =
        allocations.filterValues { it.any(block.members::contains) }.keys

    private fun Block.touches(resources: Set<String>): Boolean = resources.any { it in members }
}
