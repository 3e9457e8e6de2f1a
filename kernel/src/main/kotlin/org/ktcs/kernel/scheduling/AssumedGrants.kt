package org.ktcs.kernel.scheduling

/**
 * Grants looked at as if made ([RouteSafety.leavesDeadHole]): per client, what it holds then. What a client holds and
 * who holds a key are answered as if they were made. Assumptions nest: a second vehicle's step on top of a grant.
 */
internal class AssumedGrants(
    private val holdings: (String) -> Set<String>,
    private val holders: (String) -> Collection<String>,
) {
    private val held = HashMap<String, Set<String>>()

    operator fun contains(client: String): Boolean = client in held

    /** Runs [body] as if [client] held [keys]. */
    fun <T> assuming(client: String, keys: Set<String>, body: () -> T): T {
        val before = held.put(client, keys)
        try {
            return body()
        } finally {
            if (before == null) held.remove(client) else held[client] = before
        }
    }

    fun holdingsOf(client: String): Set<String> = held[client] ?: holdings(client)

    fun holdersOf(key: String): Collection<String> {
        val real = holders(key)
        if (held.isEmpty()) return real
        var result = real
        for ((client, keys) in held) {
            val holdsReally = client in real
            if (key in keys == holdsReally) continue
            result = if (holdsReally) result.filter { it != client } else result + client
        }
        return result
    }
}
