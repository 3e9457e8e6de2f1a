package org.ktcs.adapters.vda5050.protocol

import java.lang.invoke.MethodHandles
import java.lang.invoke.VarHandle
import java.nio.ByteOrder
import java.util.Arrays

/** Bytes [from] until [to] of [bytes], equal to another slice with the same bytes; never copied. */
internal class ByteSlice(val bytes: ByteArray, val from: Int, val to: Int) {
    private var hash = 0

    val size get() = to - from

    /** Copies the bytes into [target] from [at]; returns where they end there. */
    fun copyInto(target: ByteArray, at: Int): Int {
        System.arraycopy(bytes, from, target, at, size)
        return at + size
    }

    override fun equals(other: Any?) = other is ByteSlice && to - from == other.to - other.from &&
        Arrays.equals(bytes, from, to, other.bytes, other.from, other.to)

    override fun toString() = String(bytes, from, size, Charsets.UTF_8)

    /** Eight bytes a step: a state message's arrays are hashed element by element on every message. */
    override fun hashCode(): Int {
        if (hash == 0) {
            var h = to - from
            var i = from
            while (i + Long.SIZE_BYTES <= to) {
                val word = LONGS.get(bytes, i) as Long
                h = 31 * h + (word xor (word ushr Int.SIZE_BITS)).toInt()
                i += Long.SIZE_BYTES
            }
            while (i < to) h = 31 * h + bytes[i++]
            hash = h
        }
        return hash
    }

    private companion object {
        val LONGS: VarHandle = MethodHandles.byteArrayViewVarHandle(LongArray::class.java, ByteOrder.LITTLE_ENDIAN)
    }
}

/**
 * A JSON object message split at its top level without parsing it: each field of it as the bytes that spell it
 * (`"name": value`), and the arrays named in [arrays] element by element, each element as the bytes that spell it, so a
 * slice is exactly what the sender wrote. Only the structure is followed (strings, nesting, commas); what the slices
 * hold is for the JSON parser to read. [fields] is null, and the message to be read whole, when the structure is not
 * one JSON object whose fields and elements are separated by single commas: the parser then says what is wrong in
 * its own words.
 */
internal class StateScan(val fields: List<Field>?, val arrays: Map<String, ArrayScan>) {
    /** A field but the arrays: the bytes of its name (quotes included), of `"name": value` and of its value. */
    class Field(val name: ByteSlice, val whole: ByteSlice, val value: ByteSlice)

    /** An array field: the bytes of its whole value, and those of each element. */
    class ArrayScan(val whole: ByteSlice, val elements: List<ByteSlice>)

    /**
     * The message as JSON with only the fields [only] of [fields] and the elements at [kept] of each array [arrays]
     * has; [whole] if it was not scanned. The arrays come after the other fields, which keep their order.
     */
    fun withOnly(only: List<Field>, kept: Map<String, List<Int>>, whole: ByteArray): ByteArray {
        if (fields == null) return whole
        var size = 2 + only.sumOf { it.whole.size + 1 }
        kept.forEach { (name, indexes) ->
            size += name.length + 6 + indexes.sumOf { arrays.getValue(name).elements[it].size + 1 }
        }
        val out = ByteArray(size)
        out[0] = '{'.code.toByte()
        var at = 1
        fun put(text: String) = text.forEach { out[at++] = it.code.toByte() }
        only.forEachIndexed { i, field ->
            if (i > 0) put(",")
            at = field.whole.copyInto(out, at)
        }
        kept.forEach { (name, indexes) ->
            if (at > 1) put(",")
            put("\"$name\":[")
            indexes.forEachIndexed { i, index ->
                if (i > 0) put(",")
                at = arrays.getValue(name).elements[index].copyInto(out, at)
            }
            put("]")
        }
        put("}")
        return if (at == size) out else out.copyOf(at)
    }

    /** Scans messages, their fields named in [arrays] element by element (the last of a repeated name). */
    class Splitting(arrays: Set<String>) {
        private val quotedNames = arrays.associateBy {
            "\"$it\"".toByteArray().let { name -> ByteSlice(name, 0, name.size) }
        }

        /** [payload] scanned. */
        fun scan(payload: ByteArray): StateScan = Scanner(payload, quotedNames).scan() ?: StateScan(null, emptyMap())
    }
}
