package org.ktcs.adapters.vda5050.protocol

import tools.jackson.databind.JsonNode
import java.math.BigDecimal

/**
 * A JSON schema that a value is checked against by its bytes, without a tree: the keywords the VDA 5050 schemas use on
 * the values that change from message to message (`type` naming one type, `properties`, `required`, `items`, `enum` of
 * strings, `minimum`, `maximum`) and annotations (`format` is one in draft 2020-12). [accepts] says yes only for a value
 * the schema validator accepts; where it cannot tell cheaply (a string with an escape or beyond ASCII, an integer spelt
 * with a fraction or an exponent, anything that is not plain JSON) it says no, and the caller asks the validator,
 * whose answer and words count. A schema using any other keyword is not made into one ([of]).
 */
internal class QuickSchema private constructor(
    private val type: Type,
    private val properties: Map<String, QuickSchema>,
    private val required: Set<String>,
    /** What the elements of an array must be; null: anything. */
    val items: QuickSchema?,
    private val enum: Set<String>?,
    private val minimum: BigDecimal?,
    private val maximum: BigDecimal?,
) {
    private enum class Type { OBJECT, ARRAY, STRING, INTEGER, NUMBER, BOOLEAN, NULL }

    /** The schema of the member [name] of an object; null if it has none (then anything goes). */
    fun property(name: String): QuickSchema? = properties[name]

    /** True if [value] is a JSON value this schema accepts for sure. */
    fun accepts(value: ByteSlice): Boolean = Check(value.bytes, value.from, value.to).whole(this)

    /** True if [message] is a JSON value this schema accepts for sure. */
    fun accepts(message: ByteArray): Boolean = Check(message, 0, message.size).whole(this)

    companion object {
        private val ANNOTATIONS =
            setOf("title", "description", "examples", "format", "subtopic", "\$schema", "\$comment")
        private val KEYWORDS = ANNOTATIONS + setOf(
            "type",
            "properties",
            "required",
            "items",
            "enum",
            "minimum",
            "maximum",
        )

        /** [schema] as a quick schema; null if it uses a keyword or a form of one that this does not check. */
        fun of(schema: JsonNode): QuickSchema? {
            if (!schema.isObject || schema.properties().any { it.key !in KEYWORDS }) return null
            val typeName = schema.get("type")?.takeIf { it.isString }?.stringValue() ?: return null
            val type = Type.entries.find { it.name.lowercase() == typeName } ?: return null
            val properties = schema.get("properties")?.let { node ->
                if (!node.isObject) return null
                node.properties().associate { (name, value) -> name to (of(value) ?: return null) }
            }
            val required = schema.get("required")?.let { node -> strings(node) ?: return null }
            val items = schema.get("items")?.let { of(it) ?: return null }
            val enum = schema.get("enum")?.let { node -> strings(node)?.takeIf { type == Type.STRING } ?: return null }
            val minimum = schema.get("minimum")?.let { node ->
                node.takeIf { it.isNumber }?.decimalValue() ?: return null
            }
            val maximum = schema.get("maximum")?.let { node ->
                node.takeIf { it.isNumber }?.decimalValue() ?: return null
            }
            return QuickSchema(type, properties.orEmpty(), required.orEmpty(), items, enum, minimum, maximum)
        }

        private fun strings(node: JsonNode): Set<String>? {
            val values = node.takeIf { it.isArray }?.values() ?: return null
            return if (values.all { it.isString }) values.map { it.stringValue() }.toSet() else null
        }
    }

    /** One value's bytes [from] until [end] of [bytes] checked against a schema; a null schema accepts any value. */
    private class Check(private val bytes: ByteArray, private var at: Int, private val end: Int) {
        fun whole(schema: QuickSchema): Boolean {
            skipSpace()
            if (!value(schema, 0)) return false
            skipSpace()
            return at == end
        }

        private fun value(schema: QuickSchema?, depth: Int): Boolean {
            if (depth > MAX_DEPTH || at >= end) return false
            return when (bytes[at]) {
                OPEN_OBJECT -> schema.allows(Type.OBJECT) && members(schema, depth)
                OPEN_ARRAY -> schema.allows(Type.ARRAY) && elements(schema?.items, depth)
                QUOTE -> schema.allows(Type.STRING) && string(schema?.enum)
                T -> schema.allows(Type.BOOLEAN) && literal(TRUE)
                F -> schema.allows(Type.BOOLEAN) && literal(FALSE)
                N -> schema.allows(Type.NULL) && literal(NULL)
                else -> number(schema)
            }
        }

        private fun QuickSchema?.allows(type: Type) = this == null || this.type == type

        private fun members(schema: QuickSchema?, depth: Int): Boolean {
            at++
            val seen = HashSet<String>()
            skipSpace()
            if (!take(CLOSE_OBJECT)) {
                do {
                    skipSpace()
                    val start = at + 1
                    if (!string(null)) return false
                    val name = String(bytes, start, at - 1 - start, Charsets.ISO_8859_1)
                    seen += name // named twice, each value is checked: the validator takes the last
                    skipSpace()
                    if (!take(COLON)) return false
                    skipSpace()
                    if (!value(schema?.properties?.get(name), depth + 1)) return false
                    skipSpace()
                } while (take(COMMA))
                if (!take(CLOSE_OBJECT)) return false
            }
            return schema == null || seen.containsAll(schema.required)
        }

        private fun elements(items: QuickSchema?, depth: Int): Boolean {
            at++
            skipSpace()
            if (take(CLOSE_ARRAY)) return true
            do {
                skipSpace()
                if (!value(items, depth + 1)) return false
                skipSpace()
            } while (take(COMMA))
            return take(CLOSE_ARRAY)
        }

        /** A string of printable ASCII without escapes (anything else is the validator's to read). */
        private fun string(enum: Set<String>?): Boolean {
            if (at >= end || bytes[at] != QUOTE) return false
            val start = ++at
            while (at < end) {
                val byte = bytes[at]
                if (byte == QUOTE) {
                    at++
                    return enum == null || String(bytes, start, at - 1 - start, Charsets.ISO_8859_1) in enum
                }
                if (byte < SPACE || byte == BACKSLASH) return false // control, escape, or beyond ASCII (negative)
                at++
            }
            return false
        }

        private fun literal(word: ByteArray): Boolean {
            if (end - at < word.size) return false
            for (i in word.indices) if (bytes[at + i] != word[i]) return false
            at += word.size
            return true
        }

        // JSON's number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
        private fun number(schema: QuickSchema?): Boolean {
            val start = at
            take(MINUS)
            if (!take(ZERO) && !digits()) return false
            var whole = true
            if (take(DOT)) {
                whole = false
                if (!digits()) return false
            }
            if (take(E_LOWER) || take(E_UPPER)) {
                whole = false
                if (!take(PLUS)) take(MINUS)
                if (!digits()) return false
            }
            if (schema == null) return true
            if (schema.type != Type.NUMBER && (schema.type != Type.INTEGER || !whole)) return false
            if (schema.minimum == null && schema.maximum == null) return true
            val number = BigDecimal(String(bytes, start, at - start, Charsets.ISO_8859_1))
            return (schema.minimum == null || number >= schema.minimum) &&
                (schema.maximum == null || number <= schema.maximum)
        }

        private fun digits(): Boolean {
            val start = at
            while (at < end && bytes[at] in ZERO..NINE) at++
            return at > start
        }

        private fun take(byte: Byte): Boolean {
            if (at >= end || bytes[at] != byte) return false
            at++
            return true
        }

        private fun skipSpace() {
            while (at < end) {
                val byte = bytes[at]
                if (byte != SPACE && byte != TAB && byte != NEW_LINE && byte != RETURN) return
                at++
            }
        }
    }
}

private const val MAX_DEPTH = 32
private const val OPEN_OBJECT = '{'.code.toByte()
private const val CLOSE_OBJECT = '}'.code.toByte()
private const val OPEN_ARRAY = '['.code.toByte()
private const val CLOSE_ARRAY = ']'.code.toByte()
private const val QUOTE = '"'.code.toByte()
private const val BACKSLASH = '\\'.code.toByte()
private const val COLON = ':'.code.toByte()
private const val COMMA = ','.code.toByte()
private const val SPACE = ' '.code.toByte()
private const val TAB = '\t'.code.toByte()
private const val NEW_LINE = '\n'.code.toByte()
private const val RETURN = '\r'.code.toByte()
private const val MINUS = '-'.code.toByte()
private const val PLUS = '+'.code.toByte()
private const val DOT = '.'.code.toByte()
private const val ZERO = '0'.code.toByte()
private const val NINE = '9'.code.toByte()
private const val E_LOWER = 'e'.code.toByte()
private const val E_UPPER = 'E'.code.toByte()
private const val T = 't'.code.toByte()
private const val F = 'f'.code.toByte()
private const val N = 'n'.code.toByte()
private val TRUE = "true".toByteArray()
private val FALSE = "false".toByteArray()
private val NULL = "null".toByteArray()
