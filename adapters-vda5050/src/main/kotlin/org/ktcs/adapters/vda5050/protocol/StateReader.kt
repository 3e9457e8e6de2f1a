package org.ktcs.adapters.vda5050.protocol

import org.ktcs.adapters.vda5050.protocol.MessageValidator.toKotlinx
import tools.jackson.core.JacksonException
import tools.jackson.databind.JsonNode
import tools.jackson.databind.node.ArrayNode
import tools.jackson.databind.node.ObjectNode

/** A state message read: the message, or what is wrong with it. */
sealed interface StateRead {
    data class Valid(val state: State) : StateRead

    data class Invalid(val problems: List<String>) : StateRead
}

/**
 * Reads one vehicle's `state` messages, checked against the schema if [validate]. A vehicle repeats its state every
 * second, and the bulk of a state message (its node and edge states, action states, loads, errors and information) is
 * mostly what the last one said: an array element equal to one in the same array of the vehicle's last valid message
 * was checked and decoded then, so it is neither checked nor decoded again (when the vehicle passes a node, its node
 * and edge states lose their first element and keep the rest). The schema constrains each element of these arrays on
 * its own (no condition ties it to its index, another element or another field), so the message is valid when the
 * rest of it is. One reader per vehicle.
 */
internal class StateReader(private val validate: Boolean) {
    // The arrays of the last valid message as read, each element with what it decoded to; guarded by this.
    private var lastArrays: Map<String, ArrayNode> = emptyMap()
    private var lastElements: Map<String, Map<JsonNode, Any>> = emptyMap()
    private var lastState: State? = null

    /** [payload] (UTF-8 JSON) read as a state message; throws what decoding throws for a message that is not one. */
    @Synchronized
    fun read(payload: ByteArray): StateRead {
        val tree = try {
            MessageValidator.read(payload)
        } catch (error: JacksonException) {
            return StateRead.Invalid(MessageValidator.notJson(error).problems)
        }
        val message = tree as? ObjectNode
        val arrays = message?.let {
            REPEATING.mapNotNull { name -> (it.get(name) as? ArrayNode)?.let { array -> name to array } }.toMap()
        }.orEmpty()
        val previous = lastState
        val repeated = if (previous == null) emptySet() else arrays.filter { (name, a) -> lastArrays[name] == a }.keys
        // What is left in the message to check and decode: the elements no valid message of the vehicle had.
        val freshIndexes = arrays.mapValues { (name, array) ->
            val known = lastElements[name].orEmpty()
            if (name in repeated) emptyList() else array.indices().filter { array[it] !in known }
        }
        freshIndexes.forEach { (name, fresh) ->
            message!!.replace(name, message.arrayNode().addAll(fresh.map(arrays.getValue(name)::get)))
        }
        if (validate) {
            val problems = MessageValidator.schemaProblems(IncomingTopic.STATE, tree)
            if (problems.isNotEmpty()) return StateRead.Invalid(problems.map { located(it, freshIndexes) })
        }
        val decoded = Vda5050Json.decodeFromJsonElement(State.serializer(), tree.toKotlinx())
        val lists = arrays.mapValues { (name, array) ->
            if (name in repeated) {
                previous!!.list(name)
            } else {
                val known = lastElements[name].orEmpty()
                val fresh = decoded.list(name).iterator()
                array.values().map { element -> known[element] ?: fresh.next() }
            }
        }
        val state = if (lists.isEmpty()) decoded else decoded.with(lists)
        lastElements = arrays.mapValues { (name, array) ->
            if (name in repeated) lastElements.getValue(name) else array.values().zip(lists.getValue(name)).toMap()
        }
        lastArrays = arrays
        lastState = state
        return StateRead.Valid(state)
    }

    /** [problem] with the index of an array element as the vehicle sent it, not as it was checked. */
    private fun located(problem: String, freshIndexes: Map<String, List<Int>>): String {
        val match = ELEMENT.find(problem) ?: return problem
        val (name, index) = match.destructured
        val original = freshIndexes[name]?.getOrNull(index.toInt()) ?: return problem
        return "/$name/$original" + problem.substring(match.range.last + 1)
    }

    private fun ArrayNode.indices(): IntRange = 0 until size()

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
        val REPEATING = listOf(NODE_STATES, EDGE_STATES, ACTION_STATES, LOADS, ERRORS, INFORMATION)
        val ELEMENT = Regex("^/(${REPEATING.joinToString("|")})/(\\d+)")
    }
}
