package org.ktcs.kernel.web.ws

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import java.io.ByteArrayOutputStream

/**
 * The large fields of an event's object that a client keeping the object's latest state already has: an order under
 * way changes its step index many times a second while its drive orders and their routes (most of its JSON) stay as
 * they were, and a driving vehicle reports its position while its claimed route stays. A client that subscribes with
 * `omitUnchanged` gets events without them, and the list of what was left out (see [withoutFields]).
 */
internal object Unchanged {
    // The fields that may be left out, each with how to read it from the domain object; immutable values share what
    // did not change, so most comparisons stop at the identity check.
    private val vehicleFields: List<Pair<String, (Vehicle) -> Any?>> = listOf(
        "claimedResources" to Vehicle::claimedResources,
        "allocatedResources" to Vehicle::allocatedResources,
        "properties" to Vehicle::properties,
        "acceptableOrderTypes" to Vehicle::acceptableOrderTypes,
    )
    private val orderFields: List<Pair<String, (TransportOrder) -> Any?>> = listOf(
        "driveOrders" to TransportOrder::driveOrders,
        "properties" to TransportOrder::properties,
        "history" to TransportOrder::history,
        "dependencies" to TransportOrder::dependencies,
    )

    fun fieldsOf(event: KernelEvent): List<String> = when (event) {
        is VehicleEvent -> same(event.previous, event.current, vehicleFields)
        is TransportOrderEvent -> same(event.previous, event.current, orderFields)
        else -> emptyList()
    }

    private fun <T : Any> same(before: T?, after: T?, fields: List<Pair<String, (T) -> Any?>>): List<String> {
        if (before == null || after == null) return emptyList()
        return fields.filter { (_, read) -> read(before) == read(after) }.map { it.first }
    }
}

/**
 * [json], a JSON object as UTF-8 (as kotlinx writes it: no whitespace), without its top-level fields named in [names].
 * A scan over the bytes, far cheaper than parsing: the object's states are at hand only as bytes.
 */
internal fun withoutFields(json: ByteArray, names: Collection<String>): ByteArray =
    if (names.isEmpty()) json else rewriteFields(json, names)

/**
 * [json] (as for [withoutFields]) without its top-level fields named in [omit], and with the values of those named in
 * [replace] replaced by what their functions give (asked only for fields that are there and not omitted): in one pass
 * over the bytes, so that an encoder can leave large values out of the object it encodes and put their own bytes in.
 */
internal fun rewriteFields(
    json: ByteArray,
    omit: Collection<String>,
    replace: Map<String, () -> ByteArray> = emptyMap(),
): ByteArray {
    val omitted = omit.map { utf8("\"$it\":") }
    val replaced = replace.map { (name, value) -> utf8("\"$name\":") to value }
    val out = ByteArrayOutputStream(json.size)
    out.write(json[0].toInt())
    var at = 1
    while (at < json.size && json[at] != CLOSE_BRACE) {
        val valueAt = endOfString(json, at) + 1
        val end = endOfValue(json, valueAt)
        if (omitted.none { startsWith(json, at, it) }) {
            if (out.size() > 1) out.write(COMMA.toInt())
            val value = replaced.firstOrNull { startsWith(json, at, it.first) }?.second
            if (value == null) {
                out.write(json, at, end - at)
            } else {
                out.write(json, at, valueAt - at)
                out.write(value())
            }
        }
        at = if (end < json.size && json[end] == COMMA) end + 1 else end
    }
    out.write(CLOSE_BRACE.toInt())
    return out.toByteArray()
}

private const val QUOTE = '"'.code.toByte()
private const val BACKSLASH = '\\'.code.toByte()
private const val COMMA = ','.code.toByte()
private const val OPEN_BRACE = '{'.code.toByte()
private const val CLOSE_BRACE = '}'.code.toByte()
private const val OPEN_BRACKET = '['.code.toByte()
private const val CLOSE_BRACKET = ']'.code.toByte()

private fun startsWith(json: ByteArray, at: Int, prefix: ByteArray): Boolean {
    if (at + prefix.size > json.size) return false
    for (i in prefix.indices) if (json[at + i] != prefix[i]) return false
    return true
}

// The index just past the string whose opening quote is at [at].
private fun endOfString(json: ByteArray, at: Int): Int {
    var i = at + 1
    while (true) {
        val b = json[i]
        if (b == QUOTE) return i + 1
        i += if (b == BACKSLASH) 2 else 1
    }
}

// The index just past the value starting at [at] (a comma or the closing brace of the object follows it).
private fun endOfValue(json: ByteArray, at: Int): Int {
    var depth = 0
    var i = at
    while (i < json.size) {
        val b = json[i]
        if (b == QUOTE) {
            i = endOfString(json, i)
            continue
        }
        if (b == OPEN_BRACE || b == OPEN_BRACKET) {
            depth++
        } else if (b == CLOSE_BRACE || b == CLOSE_BRACKET) {
            if (depth == 0) return i
            depth--
        } else if (b == COMMA && depth == 0) {
            return i
        }
        i++
    }
    return i
}
