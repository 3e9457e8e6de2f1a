package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block
import org.ktcs.api.model.BlockType
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel

/** The path property naming the direction in which a path enters a SAME_DIRECTION_ONLY block (openTCS). */
const val BLOCK_ENTRY_DIRECTION: String = "tcs:blockEntryDirection"

/**
 * A SAME_DIRECTION_ONLY block a request touches, and the direction it enters it in (`null`: no entering path); for a
 * corridor ([Corridors]), whether the request comes into it from outside ([entering]) or drives on inside.
 */
internal class BlockEntry(val block: Block, val direction: String?, val entering: Boolean = true)

/** Which blocks each resource belongs to, by block type; built once per model. */
internal class BlockIndex(private val model: PlantModel) {
    private val single = membership(BlockType.SINGLE_VEHICLE_ONLY)
    private val sameDirection = membership(BlockType.SAME_DIRECTION_ONLY)

    fun singleBlocksOf(resource: String): List<Block> = single[resource].orEmpty()

    fun sameDirectionBlocksOf(resource: String): List<Block> = sameDirection[resource].orEmpty()

    /**
     * [resources] plus every member of each SINGLE_VEHICLE_ONLY block they touch. Not transitive: a member shared
     * with a second block excludes that block's users anyway, because their requests are expanded too.
     */
    fun expand(resources: Set<String>): Set<String> {
        if (single.isEmpty() || resources.none(single::containsKey)) return resources
        val blocks = resources.flatMap { singleBlocksOf(it) }
        if (blocks.isEmpty()) return resources
        return blocks.flatMapTo(LinkedHashSet(resources)) { it.members }
    }

    /** [resources] [expand]ed, plus the names of the SAME_DIRECTION_ONLY blocks they touch: deadlock avoidance's keys. */
    fun keysOf(resources: Set<String>): Set<String> {
        val expanded = expand(resources)
        val entries = entries(expanded)
        return if (entries.isEmpty()) expanded else expanded + entries.map { it.block.name }
    }

    /** The SAME_DIRECTION_ONLY blocks [resources] touch, each with the direction the resources enter it in. */
    fun entries(resources: Set<String>): List<BlockEntry> = if (resources.none(sameDirection::containsKey)) {
        emptyList()
    } else {
        entriesOf(resources)
    }

    private fun entriesOf(resources: Set<String>): List<BlockEntry> = resources
        .flatMap { sameDirectionBlocksOf(it) }
        .distinctBy { it.name }
        .map { BlockEntry(it, entryDirection(it, resources)) }

    private fun entryDirection(block: Block, resources: Set<String>): String? = resources
        .mapNotNull { model.path(it) }
        .filter { it.enters(block) }
        .map { it.properties[BLOCK_ENTRY_DIRECTION] ?: it.name }
        .minOrNull()

    // A path enters a block when it leads into it from outside: the path itself or its end is a member, its start
    // is not. This covers blocks modelled as paths only as well as blocks that include their points.
    private fun Path.enters(block: Block): Boolean =
        sourcePoint !in block.members && (name in block.members || destinationPoint in block.members)

    private fun membership(type: BlockType): Map<String, List<Block>> = model.blocks
        .filter { it.type == type }
        .flatMap { block -> block.members.map { it to block } }
        .groupBy({ it.first }, { it.second })
}
