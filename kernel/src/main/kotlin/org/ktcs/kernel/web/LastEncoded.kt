package org.ktcs.kernel.web

/**
 * What [encode] made of each object, by identity, for the [capacity] most recently changed objects (by name): a
 * driving vehicle or an order under way changes many times a second, and the state an event reports as previous is
 * the one the event before reported as current, so each state is encoded once instead of twice; a route stays the same
 * object while its order advances step by step. One instance serves every client (each state is encoded once,
 * whoever follows it), so it is safe to use from several threads.
 */
internal class LastEncoded<T : Any, E : Any>(private val capacity: Int, private val encode: (T) -> E) {
    private val last = object : LinkedHashMap<String, Pair<T, E>>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<String, Pair<T, E>>) = size > capacity
    }

    /** What the object named [name] was encoded to last, if it is still kept. */
    fun lastOf(name: String): E? = synchronized(last) { last[name]?.second }

    /** [value], the current object named [name], encoded: anew only if it is not the object encoded last. */
    fun of(name: String, value: T): E {
        synchronized(last) { last[name]?.takeIf { it.first === value }?.let { return it.second } }
        // Encoded outside the lock: two clients may encode the same state at once, which costs only time.
        val encoded = encode(value)
        synchronized(last) { last[name] = value to encoded }
        return encoded
    }
}
