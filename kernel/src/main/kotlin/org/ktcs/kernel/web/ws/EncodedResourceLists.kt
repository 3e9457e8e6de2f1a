package org.ktcs.kernel.web.ws

import org.ktcs.kernel.web.LastEncoded

/**
 * Vehicles' resource lists (claimed or allocated, per movement step) as JSON, the last one of each of the [capacity]
 * most recently changed vehicles kept. A driving vehicle's claimed list loses its first step at every allocation and
 * is otherwise the same steps (the same sets), so a list that is the end of the one encoded last is cut from its bytes
 * rather than encoded again: an event then costs a copy, not the route's length in JSON encoding. Safe to use from
 * several threads.
 */
internal class EncodedResourceLists(capacity: Int) {
    private val last = LastEncoded(capacity, ::encode)

    /** [list], the list of the vehicle named [name], as a JSON array of arrays of names. */
    fun of(name: String, list: List<Set<String>>): ByteArray {
        if (list.isEmpty()) return EMPTY
        return last.lastOf(name)?.endOf(list) ?: last.of(name, list).bytes
    }

    /** A list's JSON, and where each of its elements starts in it. */
    private class Encoded(val list: List<Set<String>>, val bytes: ByteArray, val starts: IntArray) {
        /** [other]'s JSON if it is this list or its end (the same sets, by identity), else `null`. */
        fun endOf(other: List<Set<String>>): ByteArray? {
            if (other === list) return bytes
            val skipped = list.size - other.size
            if (skipped < 0) return null
            for (i in other.indices) if (other[i] !== list[skipped + i]) return null
            val from = starts[skipped]
            val out = ByteArray(1 + bytes.size - from)
            out[0] = OPEN
            bytes.copyInto(out, 1, from)
            return out
        }
    }

    private companion object {
        val EMPTY = utf8("[]")
        const val OPEN = '['.code.toByte()
        const val COMMA = ','.code.toByte()
        const val CLOSE = ']'.code.toByte()

        // Written as kotlinx writes a list of string sets (V1Json), measured first into an array of its size.
        fun encode(list: List<Set<String>>): Encoded {
            val out = Utf8JsonOut(sizeOf(list))
            val starts = IntArray(list.size)
            list.forEachIndexed { index, step ->
                out.byte(if (index == 0) OPEN else COMMA)
                starts[index] = out.written
                out.array(step) { string(it) }
            }
            out.byte(CLOSE)
            return Encoded(list, out.toByteArray(), starts)
        }

        // The outer brackets and commas (one byte per step and one more), each step's brackets, names and commas.
        private fun sizeOf(list: List<Set<String>>): Int = list.size + 1 +
            list.sumOf { step -> 2 + maxOf(step.size - 1, 0) + step.sumOf { Utf8JsonOut.sizeOf(it) } }
    }
}
