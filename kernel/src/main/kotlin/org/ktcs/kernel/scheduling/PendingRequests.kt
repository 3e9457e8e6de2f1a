package org.ktcs.kernel.scheduling

/**
 * Requests not granted yet. A client's requests are granted in its own order, so only its oldest one (its head) is
 * a candidate. Heads are indexed by the keys they wait for, so that a release looks at its own waiters only.
 */
internal class PendingRequests {
    private val queues = LinkedHashMap<String, ArrayDeque<Request>>()
    private val waiters = HashMap<String, MutableSet<Request>>()

    fun head(client: String): Request? = queues[client]?.first()

    fun isHead(request: Request): Boolean = head(request.client.name) === request

    /** Queues [request]; returns whether it is its client's head. */
    fun add(request: Request): Boolean {
        val queue = queues.getOrPut(request.client.name, ::ArrayDeque)
        queue.addLast(request)
        if (queue.size == 1) index(request)
        return queue.size == 1
    }

    /** Removes the client's head; returns the next one, which becomes the head. */
    fun pop(client: String): Request? {
        val queue = queues[client] ?: return null
        unindex(queue.removeFirst())
        if (queue.isEmpty()) queues.remove(client)
        return queue.firstOrNull()?.also(::index)
    }

    fun clear(client: String) {
        queues.remove(client)?.let { unindex(it.first()) }
    }

    /** The heads waiting for any of [keys]. */
    fun waitingFor(keys: Set<String>): Set<Request> = keys.flatMapTo(HashSet()) { waiters[it].orEmpty() }

    fun heads(): List<Request> = queues.values.map { it.first() }

    fun snapshot(): Map<String, List<Set<String>>> = queues.mapValues { (_, queue) -> queue.map { it.resources } }

    private fun index(request: Request) {
        request.wakeKeys.forEach { waiters.getOrPut(it, ::HashSet) += request }
    }

    private fun unindex(request: Request) {
        for (key in request.wakeKeys) {
            val heads = waiters[key] ?: continue
            heads -= request
            if (heads.isEmpty()) waiters.remove(key)
        }
    }
}
