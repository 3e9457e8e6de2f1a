package org.ktcs.adapters.vda5050.protocol

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
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
 * message is first only scanned ([StateScan]) to find its fields and elements by their bytes; a tree is built, checked
 * and decoded for what changed alone. One reader per vehicle.
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
        val tree = try {
            MessageValidator.read(scan.withOnly(changed ?: scan.fields.orEmpty(), freshIndexes, payload))
        } catch (error: JacksonException) {
            return StateRead.Invalid(MessageValidator.notJson(error).problems)
        }
        if (validate) {
            val problems = if (changed == null) {
                MessageValidator.schemaProblems(IncomingTopic.STATE, tree)
            } else {
                MessageValidator.stateFieldProblems(tree)
            }
            if (problems.isNotEmpty()) return StateRead.Invalid(problems.map { located(it, freshIndexes) })
        }
        val json = tree.toKotlinx()
        val fields = (json as? JsonObject)?.filterKeys { it !in scan.arrays }.orEmpty()
        val allFields = if (changed == null) fields else last.fields + fields
        val decoded = if (changed == null) {
            Vda5050Json.decodeFromJsonElement(State.serializer(), json)
        } else {
            Vda5050Json.decodeFromJsonElement(State.serializer(), JsonObject(last.fields + json.jsonObject))
        }
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
            // Read whole, its fields are the JSON object's unless it named one twice (the parser keeps the last).
            scanned = scan.fields?.takeIf { changed != null || fields.size == it.size },
            fields = allFields,
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

    /** What the last valid message said, as the next one is read against it. */
    private class LastValid(
        /** Its fields but the arrays, as spelt; null if it was not scanned or named a field twice or as an array. */
        val scanned: List<StateScan.Field>?,
        /** Its fields but the arrays, as JSON. */
        val fields: Map<String, JsonElement>,
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
        val ELEMENT = Regex("^/(${REPEATING.joinToString("|")})/(\\d+)")
    }
}
