package org.ktcs.kernel.scheduling

/** Per client, a count of the changes to what it holds, claims or needs at the end: what [KeptRefusals] rely on. */
internal class ClientVersions {
    private val versions = HashMap<String, Long>()
    private var changes = 0L

    fun changed(client: String) {
        versions[client] = ++changes
    }

    fun of(client: String): Long = versions[client] ?: 0L
}

/**
 * Per client, the local rule's last refusal of its grant ([RouteSafety.mayGrant]), kept with the vehicles its check
 * looked at, each with its version then. The refusal holds until one of them changes what it holds, claims or needs at
 * the end: another vehicle holds nothing that any of them needs, and if it takes something they need, the check's
 * vehicles can only move less (it finds the vehicles that can move as a least fixpoint, and a key more held frees
 * nobody). So a release elsewhere, the most common reason for a retry, costs a look at the versions instead of a walk.
 */
internal class KeptRefusals(private val versions: ClientVersions) {
    private class Refusal(val keys: Set<String>, val behind: Set<String>, val names: Array<String>, val at: LongArray)

    private val refusals = HashMap<String, Refusal>()

    /** Whether [client]'s grant of [keys] (with [behind]) was refused and nothing its check looked at changed since. */
    fun stillHolds(client: String, keys: Set<String>, behind: Set<String>): Boolean {
        val refusal = refusals[client] ?: return false
        return keys == refusal.keys && behind == refusal.behind &&
            refusal.names.indices.all { versions.of(refusal.names[it]) == refusal.at[it] }
    }

    /** Keeps the refusal of [client]'s grant of [keys] (with [behind]), whose check looked at [witnesses]. */
    fun keep(client: String, keys: Set<String>, behind: Set<String>, witnesses: Collection<String>) {
        val names = witnesses.toTypedArray()
        refusals[client] = Refusal(keys, behind, names, LongArray(names.size) { versions.of(names[it]) })
    }

    fun forget(client: String) {
        refusals.remove(client)
    }
}
