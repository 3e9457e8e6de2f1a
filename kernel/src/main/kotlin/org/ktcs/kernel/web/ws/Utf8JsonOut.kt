package org.ktcs.kernel.web.ws

import kotlinx.serialization.SerializationException

/**
 * JSON values written as UTF-8 into an array that grows as needed, each exactly as [org.ktcs.kernel.web.v1.V1Json]
 * writes it and [utf8] turns that into bytes: strings escaped as kotlinx.serialization escapes them (`\"`, `\\`, the
 * short escapes and `\u00xx` for the other control characters, nothing else), a lone surrogate as `?`, numbers as
 * Kotlin/JVM's `toString` prints them. One instance per result and thread: nothing is shared.
 */
internal class Utf8JsonOut(capacity: Int) {
    private var bytes = ByteArray(capacity)
    private var size = 0

    /** How many bytes were written so far. */
    val written: Int get() = size

    fun byte(value: Byte) {
        ensure(1)
        bytes[size++] = value
    }

    /** Bytes that are already JSON (or part of it), copied as they are. */
    fun raw(value: ByteArray) {
        ensure(value.size)
        value.copyInto(bytes, size)
        size += value.size
    }

    fun int(value: Int) = long(value.toLong())

    fun long(value: Long) {
        // The one value whose magnitude a Long cannot hold.
        if (value == Long.MIN_VALUE) return ascii(value.toString())
        val length = sizeOf(value)
        ensure(length)
        var rest = if (value < 0) -value else value
        var at = size + length
        size = at
        do {
            bytes[--at] = (ZERO + (rest % DECIMAL)).toByte()
            rest /= DECIMAL
        } while (rest != 0L)
        if (value < 0) bytes[--at] = MINUS
    }

    /** A finite double as `Double.toString` prints it; kotlinx refuses the others, so this does too. */
    fun double(value: Double) {
        if (!value.isFinite()) throw SerializationException("Unexpected special floating-point value $value")
        ascii(value.toString())
    }

    /** [value] quoted and escaped, or `null`. */
    fun stringOrNull(value: String?) = if (value == null) raw(NULL) else string(value)

    /** [value] quoted and escaped. */
    fun string(value: String) {
        // Measured only where the room that any string of its length could need is not there.
        if (size + value.length * MAX_BYTES_PER_CHAR + 2 > bytes.size) ensure(sizeOf(value))
        bytes[size++] = QUOTE
        var i = 0
        while (i < value.length) {
            val char = value[i]
            when {
                char.code < ASCII_SIZE -> ascii(char)
                value.isSurrogatePairAt(i) -> codePoint(Character.toCodePoint(char, value[++i]))
                char.isSurrogate() -> bytes[size++] = UNENCODABLE
                else -> codePoint(char.code)
            }
            i++
        }
        bytes[size++] = QUOTE
    }

    /** JSON text that needs no escaping (names, punctuation, numbers), copied as it is. */
    fun raw(json: String) = raw(utf8(json))

    /** [items] as a JSON array, each written by [write]. */
    fun <T> array(items: Iterable<T>, write: Utf8JsonOut.(T) -> Unit) {
        byte(OPEN_BRACKET)
        for ((index, item) in items.withIndex()) {
            if (index > 0) byte(COMMA)
            write(item)
        }
        byte(CLOSE_BRACKET)
    }

    /** [map] as a JSON object whose values are strings, in the map's order. */
    fun stringMap(map: Map<String, String>) {
        byte(OPEN_BRACE)
        for ((index, entry) in map.entries.withIndex()) {
            if (index > 0) byte(COMMA)
            string(entry.key)
            byte(COLON)
            string(entry.value)
        }
        byte(CLOSE_BRACE)
    }

    /** What was written, in an array of its size. */
    fun toByteArray(): ByteArray = if (size == bytes.size) bytes else bytes.copyOf(size)

    // Room is ensured by the caller.
    private fun ascii(char: Char) {
        val escape = ESCAPES[char.code]
        if (escape == null) {
            bytes[size++] = char.code.toByte()
        } else {
            escape.copyInto(bytes, size)
            size += escape.size
        }
    }

    // Room is ensured by the caller; [codePoint] is not ASCII and no surrogate.
    private fun codePoint(codePoint: Int) {
        when {
            codePoint < TWO_BYTES_BELOW -> {
                bytes[size++] = (0xC0 or (codePoint shr 6)).toByte()
            }

            codePoint < Character.MIN_SUPPLEMENTARY_CODE_POINT -> {
                bytes[size++] = (0xE0 or (codePoint shr 12)).toByte()
                bytes[size++] = (0x80 or (codePoint shr 6 and 0x3F)).toByte()
            }

            else -> {
                bytes[size++] = (0xF0 or (codePoint shr 18)).toByte()
                bytes[size++] = (0x80 or (codePoint shr 12 and 0x3F)).toByte()
                bytes[size++] = (0x80 or (codePoint shr 6 and 0x3F)).toByte()
            }
        }
        bytes[size++] = (0x80 or (codePoint and 0x3F)).toByte()
    }

    // Text that is ASCII and needs no escaping: a number as `toString` prints it.
    private fun ascii(text: String) {
        ensure(text.length)
        for (char in text) bytes[size++] = char.code.toByte()
    }

    private fun ensure(room: Int) {
        if (size + room > bytes.size) bytes = bytes.copyOf(maxOf(bytes.size * 2, size + room))
    }

    companion object {
        val NULL = utf8("null")
        private val TRUE = utf8("true")
        private val FALSE = utf8("false")

        /** `true` or `false`, as bytes to copy. */
        fun booleanOf(value: Boolean): ByteArray = if (value) TRUE else FALSE

        /** How many bytes [long] writes for [value]. */
        fun sizeOf(value: Long): Int = when {
            value == Long.MIN_VALUE -> value.toString().length
            value < 0 -> 1 + digitCount(-value)
            else -> digitCount(value)
        }

        /** How many bytes [double] writes for [value]. */
        fun sizeOf(value: Double): Int = value.toString().length

        /** How many bytes [string] writes for [value]. */
        fun sizeOf(value: String): Int {
            var size = 2
            var i = 0
            while (i < value.length) {
                val char = value[i]
                size += when {
                    char.code < ASCII_SIZE -> ESCAPES[char.code]?.size ?: 1

                    value.isSurrogatePairAt(i) -> {
                        i++
                        SURROGATE_PAIR_SIZE
                    }

                    char.isSurrogate() -> 1

                    char.code < TWO_BYTES_BELOW -> 2

                    else -> THREE_BYTES
                }
                i++
            }
            return size
        }

        private const val QUOTE = '"'.code.toByte()
        private const val COMMA = ','.code.toByte()
        private const val COLON = ':'.code.toByte()
        private const val OPEN_BRACE = '{'.code.toByte()
        private const val CLOSE_BRACE = '}'.code.toByte()
        private const val OPEN_BRACKET = '['.code.toByte()
        private const val CLOSE_BRACKET = ']'.code.toByte()
        private const val MINUS = '-'.code.toByte()
        private const val ZERO = '0'.code
        private const val DECIMAL = 10L
        private const val UNENCODABLE = '?'.code.toByte()

        // A control character takes six (`\u001f`), any other char at most three; a surrogate pair takes four.
        private const val MAX_BYTES_PER_CHAR = 6

        private const val HEX = 16
        private const val ASCII_SIZE = 128

        private const val SURROGATE_PAIR_SIZE = 4
        private const val THREE_BYTES = 3
        private const val TWO_BYTES_BELOW = 0x800

        private val SHORT_ESCAPES =
            mapOf('"' to '"', '\\' to '\\', '\t' to 't', '\b' to 'b', '\n' to 'n', '\r' to 'r', '\u000C' to 'f')

        /** The escape of each ASCII character that JSON strings must not hold as it is, as kotlinx writes it. */
        private val ESCAPES: Array<ByteArray?> = arrayOfNulls<ByteArray>(ASCII_SIZE).apply {
            for (code in 0 until ' '.code) this[code] = utf8("\\u" + code.toString(HEX).padStart(4, '0'))
            for ((char, letter) in SHORT_ESCAPES) this[char.code] = utf8("\\$letter")
        }

        private fun String.isSurrogatePairAt(index: Int) =
            this[index].isHighSurrogate() && index + 1 < length && this[index + 1].isLowSurrogate()

        private fun digitCount(value: Long): Int {
            var count = 1
            var rest = value
            while (rest >= DECIMAL) {
                rest /= DECIMAL
                count++
            }
            return count
        }
    }
}

/** [text] as a JSON string in UTF-8, as [org.ktcs.kernel.web.v1.V1Json] writes it. */
internal fun jsonString(text: String): ByteArray = json(Utf8JsonOut.sizeOf(text)) { string(text) }

/** What [write] writes, in an array of its size; [capacity] is a first guess. */
internal fun json(capacity: Int = 64, write: Utf8JsonOut.() -> Unit): ByteArray =
    Utf8JsonOut(capacity).apply(write).toByteArray()
