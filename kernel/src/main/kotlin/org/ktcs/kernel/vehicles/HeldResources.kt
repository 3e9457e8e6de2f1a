package org.ktcs.kernel.vehicles

/**
 * The resources a vehicle holds, in driving order: first what it stands on, then one set per movement command it
 * was granted. Knows what can be given back once the vehicle has driven a command.
 */
class HeldResources {
    private val sets = ArrayDeque<Set<String>>()

    fun asList(): List<Set<String>> = sets.toList()

    fun isEmpty(): Boolean = sets.isEmpty()

    fun all(): Set<String> = sets.flatMapTo(HashSet()) { it }

    fun add(resources: Set<String>) {
        sets.addLast(resources)
    }

    /** Forgets everything and holds [resources] (the vehicle's position) only. */
    fun reset(resources: Set<String>) {
        sets.clear()
        if (resources.isNotEmpty()) sets.addLast(resources)
    }

    /**
     * The vehicle drove the command that was granted [driven] and now stands on [position]: returns what lies
     * behind it and is no longer needed, and keeps [position], everything granted for later commands and, behind the
     * vehicle, as many of the sets it passed as its [coverLength] still needs ([coverLength] tells how far back a
     * set's paths reach, 0 for none: the vehicle's length then decides, as openTCS's LENGTH_RESPECTED does).
     */
    fun passed(
        driven: Set<String>,
        position: String,
        coverLength: (Set<String>) -> Long = { 0 },
        vehicleLength: Long = 0,
    ): Set<String> {
        val index = sets.indexOf(driven)
        if (index < 0) return emptySet()
        val passed = (0..index).map { sets[it] }
        val kept = keptBehind(passed, coverLength, vehicleLength)
        val ahead = sets.drop(index + 1)
        val stillNeeded = (kept + ahead).flatMapTo(hashSetOf(position)) { it }
        sets.clear()
        sets.addLast(setOf(position))
        kept.forEach(sets::addLast)
        ahead.forEach(sets::addLast)
        return passed.flatMapTo(HashSet()) { it } - stillNeeded
    }

    /**
     * What the vehicle would hold behind it after driving everything it holds and then [next]: the sets its
     * [vehicleLength] still covers, [next] left out.
     */
    fun keptAfter(next: Set<String>, coverLength: (Set<String>) -> Long, vehicleLength: Long): Set<String> {
        val index = sets.indexOf(next)
        val driven = if (index >= 0) sets.take(index + 1) else sets + listOf(next)
        return keptBehind(driven, coverLength, vehicleLength).flatMapTo(HashSet()) { it } - next
    }

    /** As [keptAfter] for several [steps] ahead, none of them held yet: [steps]' last left out. */
    fun keptAfter(steps: List<Set<String>>, coverLength: (Set<String>) -> Long, vehicleLength: Long): Set<String> =
        keptBehind(sets + steps, coverLength, vehicleLength).flatMapTo(HashSet()) { it } - steps.last()

    // Newest first, keep passed sets until their paths cover the vehicle's length.
    private fun keptBehind(
        passed: List<Set<String>>,
        coverLength: (Set<String>) -> Long,
        vehicleLength: Long,
    ): List<Set<String>> {
        var covered = 0L
        val kept = ArrayDeque<Set<String>>()
        for (set in passed.asReversed()) {
            if (covered >= vehicleLength) break
            val length = coverLength(set)
            if (length <= 0) continue
            kept.addFirst(set)
            covered += length
        }
        return kept.toList()
    }

    /** Gives up everything except [keep]; returns what was given up. */
    fun releaseAllBut(keep: Set<String>): Set<String> {
        val released = all() - keep
        reset(keep)
        return released
    }
}
