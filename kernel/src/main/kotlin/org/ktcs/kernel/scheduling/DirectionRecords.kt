package org.ktcs.kernel.scheduling

import org.ktcs.api.model.Block

/**
 * The current users of each SAME_DIRECTION_ONLY block and the direction they entered it in.
 *
 * A client uses a block while it holds at least one of its members. The direction is set by the first user to
 * enter and kept until the block is empty again; it is `null` while the only user got in without an entering path
 * (e.g. placed at a member point), and then nobody else may enter, as its direction of travel is unknown.
 */
internal class DirectionRecords {
    private class Usage(var direction: String? = null, val heldMembers: HashMap<String, Int> = HashMap())

    private val usages = HashMap<String, Usage>()

    fun users(block: String): Set<String> = usages[block]?.heldMembers?.keys.orEmpty()

    /** The direction the users of [block] entered it in; `null` if nobody uses it or the direction is unknown. */
    fun direction(block: String): String? = usages[block]?.direction

    /** The direction of every block in use whose direction is known, by block name. */
    fun directions(): Map<String, String> =
        usages.mapNotNull { (block, usage) -> usage.direction?.let { block to it } }.toMap()

    /** Whether [client] may use the block of [entry]: it is alone, already inside, or enters the same way. */
    fun admits(entry: BlockEntry, client: String): Boolean {
        val usage = usages[entry.block.name] ?: return true
        return client in usage.heldMembers ||
            usage.heldMembers.isEmpty() ||
            (entry.direction != null && entry.direction == usage.direction)
    }

    /** [admits] for a corridor ([Corridors]): a client coming into it ([BlockEntry.entering]) counts as outside. */
    fun admitsHeading(entry: BlockEntry, client: String): Boolean {
        val usage = usages[entry.block.name] ?: return true
        if (usage.heldMembers.keys.none { it != client }) return true
        if (entry.direction != null && entry.direction == usage.direction) return true
        return !entry.entering && client in usage.heldMembers
    }

    /**
     * Records that [client] was granted a request with [entry], before it holds the members. Returns whether the
     * block's direction changed, which may admit waiting clients.
     */
    fun enter(entry: BlockEntry, client: String): Boolean {
        val usage = usages.getOrPut(entry.block.name) { Usage() }
        if (usage.heldMembers.keys.any { it != client }) return false
        val continuing = if (client in usage.heldMembers) usage.direction else null
        val direction = entry.direction ?: continuing
        val changed = direction != usage.direction
        usage.direction = direction
        return changed
    }

    fun memberTaken(block: Block, client: String) {
        usages.getOrPut(block.name) { Usage() }.heldMembers.merge(client, 1, Int::plus)
    }

    /** Returns whether [client] left the block, which may admit waiting clients. */
    fun memberReleased(block: Block, client: String): Boolean {
        val usage = usages[block.name] ?: return false
        val count = usage.heldMembers[client] ?: return false
        if (count > 1) {
            usage.heldMembers[client] = count - 1
            return false
        }
        usage.heldMembers.remove(client)
        if (usage.heldMembers.isEmpty()) usages.remove(block.name)
        return true
    }
}
