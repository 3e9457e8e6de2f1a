package org.ktcs.kernel.scheduling

// What deadlock avoidance ([RouteSafety]) keeps per claimed step and computes as a vehicle's look-ahead.

/** One claimed step; [stop] is the way out of where it ends if the vehicle stops there for an operation. */
internal class ClaimedStep(val keys: Set<String>, val twoWay: Boolean, val stop: Exit?, val intoDeadEnd: Boolean) {
    /** The step's resources and blocks, without corridor need keys: what holding the step means. */
    val physical: Set<String> = physicalOf(keys)
}

/** What a vehicle needs next: every [required] key and, of the ways on ([options]), any one. */
internal class LookAhead(val required: Set<String>, val options: List<Set<String>>) {
    /** Calls [action] with every key needed: the required ones, then those of each way on. */
    inline fun forEachKey(action: (String) -> Unit) {
        required.forEach(action)
        options.forEach { it.forEach(action) }
    }
}

/** A client's look-ahead as it stands, computed at [version]. */
internal class KnownLookAhead(val version: Long, val ahead: LookAhead)
