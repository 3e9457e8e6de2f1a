package org.ktcs.api.model

/** A set of points, paths and locations that the scheduler treats as one area. */
public data class Block(
    override val name: String,
    val type: BlockType = BlockType.SINGLE_VEHICLE_ONLY,
    val members: Set<String> = emptySet(),
    val layout: BlockLayout = BlockLayout(),
    override val properties: Map<String, String> = emptyMap(),
) : PlantObject

/** The rule a block enforces. */
public enum class BlockType {
    /** Only one vehicle at a time may use any of the block's members. */
    SINGLE_VEHICLE_ONLY,

    /** Several vehicles may use the block, as long as they all enter it in the same direction. */
    SAME_DIRECTION_ONLY,
}

/** How a block is drawn; [color] is `#RRGGBB`. */
public data class BlockLayout(val color: String = "#FF0000")
