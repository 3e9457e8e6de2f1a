package org.ktcs.adapters.vda5050.protocol

import kotlinx.serialization.json.JsonObject
import org.ktcs.adapters.vda5050.protocol.MessageValidator.toKotlinx
import tools.jackson.core.JacksonException

/** A state message read: the message, or what is wrong with it. */
sealed interface StateRead {
    data class Valid(val state: State) : StateRead

    data class Invalid(val problems: List<String>) : StateRead
}

/**
 * Reads one vehicle's `state` messages, checked against the schema if [validate]. A vehicle repeats its state every
 * second, and most of a state message is what the last one said: a field spelt as in the vehicle's last valid message,
 * or an element of its node and edge states, action states, loads, errors or information spelt as one in the same
 * array of that message, was checked and decoded then, so it is neither checked nor decoded again (a driving vehicle
 * changes its header, position, distance and battery, and when it passes a node its node and edge states lose their
 * first element and keep the rest). The schema constrains a state message's fields each on its own but for the ones
 * it requires, and the elements of these arrays each on its own (no condition ties one to its index, another element
 * or another field), so a message with the same fields as the last valid one is valid when what changed is. The
 * message is first only scanned ([StateScan]) to find its fields and elements by their bytes. What changed is checked
 * by its bytes where the schema allows ([QuickSchema]: plain values, as the changing ones are), the rest in a tree by
 * the schema validator; the fields and new elements are then decoded straight from their bytes. A message with other
 * fields than the last is parsed, checked and decoded whole but for its known elements. One reader per vehicle.
 */
internal class StateReader(private val validate: Boolean) {
    private var last: LastValid? = null // guarded by this

    /** [payload] (UTF-8 JSON) read as a state message; throws what decoding throws for a message that is not one. */
    @Synchronized
    fun read(payload: ByteArray): StateRead {
        val scan = SPLITTING.scan(payload)
        val last = last
        val repeated = last?.let {
            scan.arrays.filter { (name, array) -> it.arrays[name] == array.whole }.keys
        }.orEmpty()
        // What is left in the message to check and decode: the fields and elements no valid message of the vehicle had.
        val freshIndexes = scan.arrays.mapValues { (name, array) ->
            val known = last?.elements?.get(name).orEmpty()
            if (name in repeated) emptyList() else array.elements.indices.filter { array.elements[it] !in known }
        }
        val changed = last?.changedFields(scan)
        val read = if (changed == null) {
            readWhole(scan, freshIndexes, payload)
        } else {
            readChanges(scan, changed, freshIndexes, payload)
        }
        val decoded = (read as? Read.Decoded)?.state ?: return (read as Read.Rejected).invalid
        val lists = scan.arrays.mapValues { (name, array) ->
            if (name in repeated) {
                last!!.state.list(name)
            } else {
                val known = last?.elements?.get(name).orEmpty()
                val fresh = decoded.list(name).iterator()
                array.elements.map { element -> known[element] ?: fresh.next() }
            }
        }
        val state = if (lists.isEmpty()) decoded else decoded.with(lists)
        this.last = LastValid(
            scanned = scan.fields?.takeIf { changed != null || read.fieldsRead == it.size },
            arrays = scan.arrays.mapValues { it.value.whole },
            elements = scan.arrays.mapValues { (name, array) ->
                if (name in repeated) {
                    last!!.elements.getValue(
                        name,
                    )
                } else {
                    array.elements.zip(lists.getValue(name)).toMap()
                }
            },
            state = state,
        )
        return StateRead.Valid(state)
    }

    /** A message read for what it says but its known array elements: decoded (with how many fields), or rejected. */
    private sealed interface Read {
        class Decoded(val state: State, val fieldsRead: Int) : Read

        class Rejected(val invalid: StateRead.Invalid) : Read
    }

    /** The message's fields and its [fresh] elements parsed into a tree, checked against the whole schema, decoded. */
    private fun readWhole(scan: StateScan, fresh: Map<String, List<Int>>, payload: ByteArray): Read {
        val tree = try {
            MessageValidator.read(scan.withOnly(scan.fields.orEmpty(), fresh, payload))
        } catch (error: JacksonException) {
            return Read.Rejected(StateRead.Invalid(MessageValidator.notJson(error).problems))
        }
        if (validate) {
            val problems = MessageValidator.schemaProblems(IncomingTopic.STATE, tree)
            if (problems.isNotEmpty()) return Read.Rejected(StateRead.Invalid(problems.map { located(it, fresh) }))
        }
        val json = tree.toKotlinx()
        // Read whole, its fields are the JSON object's unless it named one twice (the parser keeps the last).
        val fieldsRead = (json as? JsonObject)?.keys?.count { it !in scan.arrays } ?: 0
        return Read.Decoded(Vda5050Json.decodeFromJsonElement(State.serializer(), json), fieldsRead)
    }

    /**
     * A message with the fields of the last valid one: the [changed] fields and the [fresh] elements checked (by their
     * bytes where the schema allows, [QuickSchema]; the rest in a tree against the schema without `required`), then
     * its fields and fresh elements decoded straight from their bytes.
     */
    private fun readChanges(
        scan: StateScan,
        changed: List<StateScan.Field>,
        fresh: Map<String, List<Int>>,
        payload: ByteArray,
    ): Read {
        val fields = scan.fields!!
        if (validate) {
            val quick = QUICK
            val slowFields = changed.filter { quick?.property(it.name.unquoted())?.accepts(it.value) != true }
            val slowIndexes = fresh.mapValues { (name, indexes) ->
                val items = quick?.property(name)?.items
                indexes.filter { items?.accepts(scan.arrays.getValue(name).elements[it]) != true }
            }
            if (slowFields.isNotEmpty() || slowIndexes.values.any { it.isNotEmpty() }) {
                val tree = try {
                    MessageValidator.read(scan.withOnly(slowFields, slowIndexes, payload))
                } catch (error: JacksonException) {
                    return Read.Rejected(StateRead.Invalid(MessageValidator.notJson(error).problems))
                }
                val problems = MessageValidator.stateFieldProblems(tree)
                if (problems.isNotEmpty()) {
                    return Read.Rejected(StateRead.Invalid(problems.map { located(it, slowIndexes) }))
                }
            }
        }
        val text = String(scan.withOnly(fields, fresh, payload), Charsets.UTF_8)
        return Read.Decoded(Vda5050Json.decodeFromString(State.serializer(), text), fields.size)
    }

    private fun ByteSlice.unquoted() = String(bytes, from + 1, size - 2, Charsets.UTF_8)

    /** What the last valid message said, as the next one is read against it. */
    private class LastValid(
        /** Its fields but the arrays, as spelt; null if it was not scanned or named a field twice or as an array. */
        val scanned: List<StateScan.Field>?,
        val arrays: Map<String, ByteSlice>,
        /** The elements of each of its arrays, as spelt, with what each decoded to. */
        val elements: Map<String, Map<ByteSlice, Any>>,
        val state: State,
    ) {
        /**
         * The fields of [scan] not spelt as in this message; null if [scan] does not name the same fields in the same
         * order (and the same arrays) as this message.
         */
        fun changedFields(scan: StateScan): List<StateScan.Field>? {
            val fields = scan.fields ?: return null
            if (scanned == null || fields.size != scanned.size || arrays.keys != scan.arrays.keys) return null
            val changed = ArrayList<StateScan.Field>()
            fields.forEachIndexed { i, field ->
                val before = scanned[i]
                if (field.name != before.name) return null
                if (field.value != before.value) changed += field
            }
            return changed
        }
    }

    /** [problem] with the index of an array element as the vehicle sent it, not as it was checked. */
    private fun located(problem: String, freshIndexes: Map<String, List<Int>>): String {
        val match = ELEMENT.find(problem) ?: return problem
        val (name, index) = match.destructured
        val original = freshIndexes[name]?.getOrNull(index.toInt()) ?: return problem
        return "/$name/$original" + problem.substring(match.range.last + 1)
    }

    private fun State.list(name: String): List<Any> = when (name) {
        NODE_STATES -> nodeStates
        EDGE_STATES -> edgeStates
        ACTION_STATES -> actionStates
        LOADS -> loads.orEmpty()
        ERRORS -> errors
        else -> information.orEmpty()
    }

    @Suppress("UNCHECKED_CAST")
    private fun State.with(lists: Map<String, List<Any>>) = copy(
        nodeStates = lists[NODE_STATES] as List<NodeState>? ?: nodeStates,
        edgeStates = lists[EDGE_STATES] as List<EdgeState>? ?: edgeStates,
        actionStates = lists[ACTION_STATES] as List<ActionState>? ?: actionStates,
        loads = lists[LOADS] as List<Load>? ?: loads,
        errors = lists[ERRORS] as List<VehicleError>? ?: errors,
        information = lists[INFORMATION] as List<Information>? ?: information,
    )

    private companion object {
        const val NODE_STATES = "nodeStates"
        const val EDGE_STATES = "edgeStates"
        const val ACTION_STATES = "actionStates"
        const val LOADS = "loads"
        const val ERRORS = "errors"
        const val INFORMATION = "information"
        val REPEATING = setOf(NODE_STATES, EDGE_STATES, ACTION_STATES, LOADS, ERRORS, INFORMATION)
        val SPLITTING = StateScan.Splitting(REPEATING)
        val QUICK by lazy { MessageValidator.quickSchema(IncomingTopic.STATE) }
        val ELEMENT = Regex("^/(${REPEATING.joinToString("|")})/(\\d+)")
    }
}
