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
     * behind it and is no longer needed, and keeps [position] plus everything granted for later commands.
     */
    fun passed(driven: Set<String>, position: String): Set<String> {
        val index = sets.indexOf(driven)
        if (index < 0) return emptySet()
        val behind = (0..index).flatMapTo(HashSet()) { sets[it] }
        val ahead = sets.drop(index + 1)
        val stillNeeded = ahead.flatMapTo(hashSetOf(position)) { it }
        sets.clear()
        sets.addLast(setOf(position))
        ahead.forEach(sets::addLast)
        return behind - stillNeeded
    }

    /** Gives up everything except [keep]; returns what was given up. */
    fun releaseAllBut(keep: Set<String>): Set<String> {
        val released = all() - keep
        reset(keep)
        return released
    }
}
