package org.ktcs.kernel.web.ws

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import java.io.ByteArrayOutputStream
import java.util.concurrent.ConcurrentHashMap

/**
 * The large fields of an event's object that a client keeping the object's latest state already has: an order under
 * way changes its step index many times a second while its drive orders and their routes (most of its JSON) stay as
 * they were, and a driving vehicle reports its position while its claimed route, its bounding box, energy thresholds,
 * state and layout stay. Small fields are always sent: naming them in the list would cost more than their values. A
 * client that subscribes with `omitUnchanged` gets events without them, and the list of what was left out (see
 * [withoutFields]).
 */
internal object Unchanged {
    // The fields that may be left out, each with how to read it from the domain object; immutable values share what
    // did not change, so most comparisons stop at the identity check.
    private val vehicleFields: List<Pair<String, (Vehicle) -> Any?>> = listOf(
        "claimedResources" to Vehicle::claimedResources,
        "allocatedResources" to Vehicle::allocatedResources,
        "properties" to Vehicle::properties,
        "acceptableOrderTypes" to Vehicle::acceptableOrderTypes,
        "boundingBox" to Vehicle::boundingBox,
        "energyLevelThresholdSet" to Vehicle::energyLevelThresholdSet,
        "loadHandlingDevices" to Vehicle::loadHandlingDevices,
        "state" to { it.state to it.stateTimestamp },
        "procState" to { it.procState to it.procStateTimestamp },
        "layout" to Vehicle::layout,
    )
    private val orderFields: List<Pair<String, (TransportOrder) -> Any?>> = listOf(
        "driveOrders" to TransportOrder::driveOrders,
        "properties" to TransportOrder::properties,
        "history" to TransportOrder::history,
        "dependencies" to TransportOrder::dependencies,
        "creationTime" to TransportOrder::creationTime,
        "deadline" to TransportOrder::deadline,
        "finishedTime" to TransportOrder::finishedTime,
    )

    fun fieldsOf(event: KernelEvent): List<String> = when (event) {
        is VehicleEvent -> same(event.previous, event.current, vehicleFields)
        is TransportOrderEvent -> same(event.previous, event.current, orderFields)
        else -> emptyList()
    }

    /**
     * A vehicle's resource lists that are the lists before without their first entries, each with how many went: a
     * vehicle granted its next step or releasing what it passed loses the head of its claimed or allocated route and
     * keeps the rest, which a client that has the list before can cut itself (`shortenedLists`).
     */
    fun shortenedOf(event: KernelEvent): Map<String, Int> {
        if (event !is VehicleEvent) return emptyMap()
        val (before, after) = (event.previous ?: return emptyMap()) to (event.current ?: return emptyMap())
        val shortened = LinkedHashMap<String, Int>(2)
        for ((name, read) in resourceLists) {
            val dropped = droppedFromFront(read(before), read(after))
            if (dropped > 0) shortened[name] = dropped
        }
        return shortened
    }

    private val resourceLists: List<Pair<String, (Vehicle) -> List<Set<String>>>> = listOf(
        "claimedResources" to Vehicle::claimedResources,
        "allocatedResources" to Vehicle::allocatedResources,
    )

    // How many entries [before] lost from its front to become [after], or 0 if [after] is not such a tail of it.
    private fun <E> droppedFromFront(before: List<E>, after: List<E>): Int {
        val dropped = before.size - after.size
        if (dropped <= 0) return 0
        for (i in after.indices) if (after[i] != before[i + dropped]) return 0
        return dropped
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

/** [json] (as for [withoutFields]) without its top-level fields named in [omit], in one pass over the bytes. */
internal fun rewriteFields(json: ByteArray, omit: Collection<String>): ByteArray {
    val omitted = omit.map(::keyOf)
    val out = ByteArrayOutputStream(json.size)
    out.write(json[0].toInt())
    var at = 1
    while (at < json.size && json[at] != CLOSE_BRACE) {
        val end = endOfValue(json, endOfString(json, at) + 1)
        if (omitted.none { startsWith(json, at, it) }) {
            if (out.size() > 1) out.write(COMMA.toInt())
            out.write(json, at, end - at)
        }
        at = if (end < json.size && json[end] == COMMA) end + 1 else end
    }
    out.write(CLOSE_BRACE.toInt())
    return out.toByteArray()
}

// A field's key as it starts the field in the JSON (`"name":`), made once per name: only the objects' own field names
// come here, so the map stays small.
private val keys = ConcurrentHashMap<String, ByteArray>()

private fun keyOf(name: String): ByteArray = keys.computeIfAbsent(name) { utf8("\"$it\":") }

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
