package org.ktcs.adapters.vda5050

import kotlinx.serialization.json.JsonPrimitive
import org.ktcs.adapters.vda5050.protocol.Action
import org.ktcs.adapters.vda5050.protocol.ActionParameter
import org.ktcs.adapters.vda5050.protocol.Vda

/**
 * Maps kTCS operations and the `vda5050:action.*` / `vda5050:destinationAction.*` properties of points, paths,
 * locations, location types and orders to VDA 5050 actions, as openTCS's driver does.
 */
internal class ActionMapping(
    private val properties: Vda5050Properties,
    private val vehicleProperties: Map<String, String>,
) {
    private var nextId = 0L

    /**
     * The action for destination operation [operation]; [sources] are the property maps from the least to the most
     * specific (location type, location, order destination).
     */
    fun destinationAction(operation: String, sources: List<Map<String, String>>): Action {
        val merged = sources.fold(emptyMap<String, String>()) { all, next -> all + next }
        if (operation.equals(properties.rechargeOperation, ignoreCase = true)) {
            return Action(Vda.START_CHARGING, newId(), "SOFT")
        }
        val type = merged["${ACTION_TYPE_PREFIX}$operation"] ?: vehicleProperties["${ACTION_TYPE_PREFIX}$operation"]
            ?: DEFAULT_TYPES[operation.lowercase()] ?: operation
        val specific = "vda5050:destinationAction.$operation."
        val blocking = merged["${specific}blockingType"] ?: merged["vda5050:destinationAction.blockingType"]
            ?: if (type == Vda.PICK || type == Vda.DROP) "HARD" else "NONE"
        val parameters = parameters(
            merged,
            "${specific}parameter.",
        ) + parameters(merged, "vda5050:destinationAction.parameter.")
        return Action(type, newId(), overridden(type, blocking), parameters.distinctBy { it.key })
    }

    /** The actions `vda5050:action.<INDEX>` an element's [elementProperties] define, ordered by their index. */
    fun elementActions(elementProperties: Map<String, String>): List<Action> = elementProperties.keys
        .filter { it.startsWith(ACTION_PREFIX) && it.count { c -> c == '.' } == 1 }
        .sorted()
        .map { key ->
            val type = elementProperties.getValue(key)
            Action(
                type,
                newId(),
                overridden(type, elementProperties["$key.blockingType"] ?: "NONE"),
                parameters(elementProperties, "$key.parameter."),
            )
        }

    fun newId(): String = "ktcs-${++nextId}"

    private fun overridden(type: String, blocking: String): String {
        val chosen = vehicleProperties["$ACTION_PREFIX$type.blockingType"] ?: blocking
        return chosen.uppercase().takeIf { it in BLOCKING_TYPES } ?: "NONE"
    }

    private fun parameters(source: Map<String, String>, prefix: String): List<ActionParameter> = source
        .filterKeys { it.startsWith(prefix) }
        .map { (key, value) -> ActionParameter(key.removePrefix(prefix), typed(value)) }

    private fun typed(value: String): JsonPrimitive = when {
        value.startsWith("float:") -> value.removePrefix("float:").toDoubleOrNull()?.let(::JsonPrimitive)
        value.startsWith("integer:") -> value.removePrefix("integer:").toLongOrNull()?.let(::JsonPrimitive)
        value.startsWith("boolean:") -> value.removePrefix("boolean:").toBooleanStrictOrNull()?.let(::JsonPrimitive)
        value.startsWith("string:") -> JsonPrimitive(value.removePrefix("string:"))
        else -> null
    } ?: JsonPrimitive(value)

    companion object {
        const val ACTION_PREFIX = "vda5050:action."

        /** `vda5050:actionType.<operation> = pick`: which VDA action a kTCS operation is (kTCS's addition). */
        const val ACTION_TYPE_PREFIX = "vda5050:actionType."
        private val BLOCKING_TYPES = setOf("NONE", "SOFT", "HARD")

        /** The demo plant's and openTCS's usual operation names for picking up and dropping a load. */
        private val DEFAULT_TYPES = mapOf(
            "load cargo" to Vda.PICK,
            "unload cargo" to Vda.DROP,
            "pick" to Vda.PICK,
            "drop" to Vda.DROP,
        )
    }
}
