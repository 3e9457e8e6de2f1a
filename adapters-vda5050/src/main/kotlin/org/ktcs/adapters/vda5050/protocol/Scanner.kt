package org.ktcs.adapters.vda5050.protocol

/**
 * Follows the structure of the JSON object in [bytes] for [StateScan]: where each top-level field and each element of
 * the arrays whose quoted names (as bytes) [arrays] maps to their names begin and end. Null when the structure is not
 * one object of fields separated by single commas (what the parser should report). Runs on every state message of
 * every vehicle, hence the plain loops over the bytes.
 */
internal class Scanner(private val bytes: ByteArray, private val arrays: Map<ByteSlice, String>) {
    private var at = 0

    fun scan(): StateScan? {
        skipSpace()
        if (!take(OPEN_OBJECT)) return null
        val fields = ArrayList<StateScan.Field>()
        val scanned = HashMap<String, StateScan.ArrayScan>()
        skipSpace()
        if (!take(CLOSE_OBJECT)) {
            do {
                skipSpace()
                val start = at
                if (!string()) return null
                val name = ByteSlice(bytes, start, at)
                val arrayName = arrays[name]
                skipSpace()
                if (!take(COLON)) return null
                skipSpace()
                val valueStart = at
                val isArray = arrayName != null && peek() == OPEN_ARRAY.toInt()
                val elements = if (isArray) elements() ?: return null else null
                if (elements == null && !value()) return null
                if (arrayName == null || elements == null) {
                    fields += StateScan.Field(name, ByteSlice(bytes, start, at), ByteSlice(bytes, valueStart, at))
                } else {
                    scanned[arrayName] = StateScan.ArrayScan(ByteSlice(bytes, valueStart, at), elements)
                }
                skipSpace()
            } while (take(COMMA))
            if (!take(CLOSE_OBJECT)) return null
        }
        skipSpace()
        return if (at == bytes.size) StateScan(fields, scanned) else null
    }

    /** The elements of the array at [at], which ends up after it; null if it does not end or has an empty element. */
    private fun elements(): List<ByteSlice>? {
        at++
        val elements = ArrayList<ByteSlice>()
        skipSpace()
        if (take(CLOSE_ARRAY)) return elements
        do {
            skipSpace()
            val start = at
            if (!value()) return null
            elements += ByteSlice(bytes, start, at)
            skipSpace()
        } while (take(COMMA))
        return if (take(CLOSE_ARRAY)) elements else null
    }

    /** Steps over one value (its structure only); false if there is none or it does not end. */
    private fun value(): Boolean {
        val bytes = bytes
        val start = at
        var depth = 0
        var i = at
        while (i < bytes.size) {
            val byte = bytes[i]
            if (byte == QUOTE) {
                at = i
                if (!string()) return false
                i = at
                if (depth == 0) break
                continue
            }
            if (byte == OPEN_OBJECT || byte == OPEN_ARRAY) {
                depth++
            } else if (byte == CLOSE_OBJECT || byte == CLOSE_ARRAY) {
                if (depth == 0) break
                if (--depth == 0) {
                    i++
                    break
                }
            } else if (depth == 0 && (byte == COMMA || byte.isSpace())) {
                break
            }
            i++
        }
        at = i
        return depth == 0 && at > start
    }

    /** Steps over the string starting at [at]; false if there is none or it does not end. */
    private fun string(): Boolean {
        val bytes = bytes
        if (at >= bytes.size || bytes[at] != QUOTE) return false
        var i = at + 1
        while (i < bytes.size) {
            val byte = bytes[i]
            if (byte == QUOTE) {
                at = i + 1
                return true
            }
            i += if (byte == BACKSLASH) 2 else 1
        }
        return false
    }

    private fun peek(): Int = if (at < bytes.size) bytes[at].toInt() else -1

    private fun take(byte: Byte): Boolean {
        if (at >= bytes.size || bytes[at] != byte) return false
        at++
        return true
    }

    private fun skipSpace() {
        while (at < bytes.size && bytes[at].isSpace()) at++
    }

    private fun Byte.isSpace() = this == SPACE || this == TAB || this == NEW_LINE || this == RETURN

    private companion object {
        const val OPEN_OBJECT = '{'.code.toByte()
        const val CLOSE_OBJECT = '}'.code.toByte()
        const val OPEN_ARRAY = '['.code.toByte()
        const val CLOSE_ARRAY = ']'.code.toByte()
        const val QUOTE = '"'.code.toByte()
        const val BACKSLASH = '\\'.code.toByte()
        const val COLON = ':'.code.toByte()
        const val COMMA = ','.code.toByte()
        const val SPACE = ' '.code.toByte()
        const val TAB = '\t'.code.toByte()
        const val NEW_LINE = '\n'.code.toByte()
        const val RETURN = '\r'.code.toByte()
    }
}
