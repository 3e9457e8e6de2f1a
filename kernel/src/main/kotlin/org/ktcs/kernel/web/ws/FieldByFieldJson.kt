package org.ktcs.kernel.web.ws

/**
 * The top-level fields of an object that [FieldByFieldJson] writes: [all] in the object's order, each with the bytes
 * of its key (`"name":`) and a bit of its own in the sets of fields left out.
 */
internal class JsonFields<F : Enum<F>>(val all: Array<F>, wireName: (F) -> String) {
    private val keys: Array<ByteArray> = Array(all.size) { jsonString(wireName(all[it])) + ':'.code.toByte() }
    private val byWireName: Map<String, F> = all.associateBy(wireName)

    init {
        require(all.size <= Int.SIZE_BITS) { "at most ${Int.SIZE_BITS} fields fit the bits, not ${all.size}" }
    }

    fun keyOf(field: F): ByteArray = keys[field.ordinal]

    fun bitOf(field: F): Int = 1 shl field.ordinal

    /** The bits of all fields. */
    val allBits: Int = all.fold(0) { bits, field -> bits or bitOf(field) }

    /** The bits of the fields named [wireNames]; names of no field are ignored. */
    fun bitsOf(wireNames: List<String>): Int =
        wireNames.fold(0) { bits, name -> bits or (byWireName[name]?.let(::bitOf) ?: 0) }
}

/**
 * An object's state as UTF-8 JSON written field by field, whole or without some of its top-level [fields]. Each result
 * is measured first and written into a new array of its size, so one instance serves several threads.
 */
internal abstract class FieldByFieldJson<F : Enum<F>>(private val fields: JsonFields<F>) : MarkedJson {
    override val full: ByteArray by lazy { write(omitted = 0) }

    override fun without(fields: List<String>): ByteArray = write(this.fields.bitsOf(fields))

    override fun only(fields: List<String>): ByteArray =
        write(this.fields.allBits and this.fields.bitsOf(fields).inv(), absentAsNull = true)

    /**
     * Whether [field] is in the object at all: kotlinx leaves some fields out while they are `null`. A field that is not
     * must write `null` when asked to (see [only]).
     */
    protected open fun isPresent(field: F): Boolean = true

    protected abstract fun writeValue(field: F, out: Utf8JsonOut)

    /** The bytes [writeValue] writes for [field]. */
    protected abstract fun sizeOfValue(field: F): Int

    /**
     * The object without the fields whose bits ([JsonFields.bitOf]) are set in [omitted]; with [absentAsNull], a field
     * that is left out while it is `null` is written as `null` (a client merging changes learns that it went).
     */
    private fun write(omitted: Int, absentAsNull: Boolean = false): ByteArray {
        val out = Utf8JsonOut(size(omitted, absentAsNull))
        out.byte(OPEN_BRACE)
        var written = 0
        for (field in fields.all) {
            if (!isWritten(field, omitted, absentAsNull)) continue
            if (written++ > 0) out.byte(COMMA)
            out.raw(fields.keyOf(field))
            writeValue(field, out)
        }
        out.byte(CLOSE_BRACE)
        return out.toByteArray()
    }

    private fun size(omitted: Int, absentAsNull: Boolean): Int {
        var size = 2
        var written = 0
        for (field in fields.all) {
            if (!isWritten(field, omitted, absentAsNull)) continue
            if (written++ > 0) size++
            size += fields.keyOf(field).size + sizeOfValue(field)
        }
        return size
    }

    private fun isWritten(field: F, omitted: Int, absentAsNull: Boolean) =
        omitted and fields.bitOf(field) == 0 && (absentAsNull || isPresent(field))

    private companion object {
        const val OPEN_BRACE = '{'.code.toByte()
        const val CLOSE_BRACE = '}'.code.toByte()
        const val COMMA = ','.code.toByte()
    }
}
