package org.ktcs.kernel.workingset

import org.ktcs.api.kernel.KernelClock

/**
 * Completes incomplete names with a suffix in the form of a ULID: 26 characters of Crockford base 32, the first ten
 * the creation time in milliseconds, the rest a counter. Names sort by creation time and never repeat. Unlike a
 * random ULID, the counter keeps simulations reproducible.
 */
class ObjectNames(private val clock: KernelClock) : NamesUsed {
    private var lastMillis = -1L
    private var counter = 0L

    /** The millisecond of the last name completed (-1 before the first); kept by the state store. */
    override val lastMillisUsed: Long get() = lastMillis

    /** The counter of the last name completed within [lastMillisUsed]. */
    override val lastCounterUsed: Long get() = counter

    /** Continues after the name made at [millis] with [counter] (the position of a previous run). */
    fun resumeAfter(millis: Long, counter: Long) {
        lastMillis = millis
        this.counter = counter
    }

    fun complete(prefix: String): String {
        // Never behind the last name made, so that a clock set back (or a restart on a slower clock) reuses none.
        val millis = maxOf(clock.now().toEpochMilli(), lastMillis)
        counter = if (millis == lastMillis) counter + 1 else 0
        lastMillis = millis
        return prefix + encode(millis, TIME_CHARACTERS) + encode(counter, COUNTER_CHARACTERS)
    }

    private fun encode(value: Long, length: Int): String {
        val out = CharArray(length)
        var rest = value
        for (index in length - 1 downTo 0) {
            out[index] = ALPHABET[(rest and 31).toInt()]
            rest = rest ushr 5
        }
        return String(out)
    }

    private companion object {
        const val ALPHABET = "0123456789ABCDEFGHJKMNPQRSTVWXYZ"
        const val TIME_CHARACTERS = 10
        const val COUNTER_CHARACTERS = 16
    }
}
