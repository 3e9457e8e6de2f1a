package org.ktcs.adapters.vda5050.protocol

import org.ktcs.adapters.vda5050.protocol.MessageValidator.toKotlinx
import tools.jackson.core.JacksonException
import tools.jackson.databind.JsonNode
import tools.jackson.databind.node.ObjectNode

/** A state message read: the message, or what is wrong with it. */
sealed interface StateRead {
    data class Valid(val state: State) : StateRead

    data class Invalid(val problems: List<String>) : StateRead
}

/**
 * Reads one vehicle's `state` messages, checked against the schema if [validate]. A vehicle repeats its state every
 * second, and the bulk of a state message (its node and edge states, action states, loads, errors and information) is
 * mostly what the last one said: an array equal to the one in the vehicle's last valid message was checked and decoded
 * then, so it is neither checked nor decoded again. The schema constrains each of these arrays on its own (no condition
 * ties them to another field), so the message is valid when the rest of it is. One reader per vehicle.
 */
internal class StateReader(private val validate: Boolean) {
    // The arrays of the last valid message as read, and the message decoded; guarded by this.
    private var lastArrays: Map<String, JsonNode> = emptyMap()
    private var lastState: State? = null

    /** [payload] (UTF-8 JSON) read as a state message; throws what decoding throws for a message that is not one. */
    @Synchronized
    fun read(payload: ByteArray): StateRead {
        val tree = try {
            MessageValidator.read(payload)
        } catch (error: JacksonException) {
            return StateRead.Invalid(MessageValidator.notJson(error).problems)
        }
        val arrays = (tree as? ObjectNode)?.let { message ->
            REPEATING.mapNotNull { name -> message.get(name)?.takeIf { it.isArray }?.let { name to it } }.toMap()
        }.orEmpty()
        val previous = lastState
        val repeated = if (previous == null) {
            emptySet()
        } else {
            arrays.filter { (name, array) ->
                lastArrays[name] == array
            }.keys
        }
        repeated.forEach { (tree as ObjectNode).replace(it, tree.arrayNode()) }
        if (validate) {
            val problems = MessageValidator.schemaProblems(IncomingTopic.STATE, tree)
            if (problems.isNotEmpty()) return StateRead.Invalid(problems)
        }
        val decoded = Vda5050Json.decodeFromJsonElement(State.serializer(), tree.toKotlinx())
        val state = if (previous == null || repeated.isEmpty()) decoded else decoded.repeating(previous, repeated)
        lastArrays = arrays
        lastState = state
        return StateRead.Valid(state)
    }

    private fun State.repeating(previous: State, repeated: Set<String>) = copy(
        nodeStates = if (NODE_STATES in repeated) previous.nodeStates else nodeStates,
        edgeStates = if (EDGE_STATES in repeated) previous.edgeStates else edgeStates,
        actionStates = if (ACTION_STATES in repeated) previous.actionStates else actionStates,
        loads = if (LOADS in repeated) previous.loads else loads,
        errors = if (ERRORS in repeated) previous.errors else errors,
        information = if (INFORMATION in repeated) previous.information else information,
    )

    private companion object {
        const val NODE_STATES = "nodeStates"
        const val EDGE_STATES = "edgeStates"
        const val ACTION_STATES = "actionStates"
        const val LOADS = "loads"
        const val ERRORS = "errors"
        const val INFORMATION = "information"
        val REPEATING = listOf(NODE_STATES, EDGE_STATES, ACTION_STATES, LOADS, ERRORS, INFORMATION)
    }
}
