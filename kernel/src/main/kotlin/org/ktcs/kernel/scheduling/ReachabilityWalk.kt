package org.ktcs.kernel.scheduling

/**
 * The local rule's check ([RouteSafety]): which vehicles could never move again while [grantee] holds [held] and
 * stands. The vehicles near enough to matter are those whose needs the grantee's needs lead to. Among them the ones
 * that can move are found as a least fixpoint (a vehicle can move once what it needs is free or held by vehicles that
 * can move; for the ways on, once one of them is), and all others wait. Waiting is thus the greatest fixpoint, not the
 * least: two vehicles that each need the other only because the grantee holds their one other way on (a vehicle
 * standing between them on a two-way track, with a bay beside it) wait, though neither waits for the grantee directly.
 * [pinned]: a vehicle that stays where it stands, whatever it needs; [lookAhead]: a vehicle's look-ahead as it stands.
 */
internal class ReachabilityWalk(
    private val grantee: String,
    private val held: Set<String>,
    private val pinned: String?,
    private val assumed: AssumedGrants,
    private val lookAhead: (String) -> LookAhead,
) {
    private val waiting = HashSet<String>()
    private var near: Map<String, LookAhead> = emptyMap()

    /** The vehicles the grantee's check looked at: those whose needs its needs lead to. */
    fun reached(): Set<String> = near.keys

    fun isBlocked(ahead: LookAhead, self: String): Boolean {
        if (self == grantee) settle(ahead)
        return blocks(ahead, self)
    }

    private fun blocks(ahead: LookAhead, self: String): Boolean =
        ahead.required.any { isTaken(it, self) } ||
            (ahead.options.isNotEmpty() && ahead.options.all { option -> option.any { isTaken(it, self) } })

    fun isTaken(key: String, self: String): Boolean =
        (self != grantee && key in held) || assumed.holdersOf(key).any { it != self && it in waiting }

    private fun settle(start: LookAhead) {
        val near = LinkedHashMap<String, LookAhead>()
        val queue = ArrayDeque<String>()
        fun reach(ahead: LookAhead) {
            ahead.forEachKey { key ->
                for (holder in assumed.holdersOf(key)) {
                    if (holder != grantee && holder !in near) {
                        near[holder] = lookAhead(holder)
                        queue += holder
                    }
                }
            }
        }
        reach(start)
        while (queue.isNotEmpty()) reach(near.getValue(queue.removeFirst()))
        this.near = near
        waiting += near.keys
        val order = near.keys.reversed()
        do {
            var changed = false
            for (client in order) {
                if (client in waiting && client != pinned && !blocks(near.getValue(client), client)) {
                    waiting -= client
                    changed = true
                }
            }
        } while (changed)
    }
}
