package org.ktcs.kernel.web.contract

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject

/**
 * Fields kTCS adds to openTCS's objects. kTCS's own document describes them (and checks them); openTCS's schemas,
 * which forbid unknown properties, are checked against the JSON without them, as an openTCS client that ignores
 * them sees it.
 */
object KtcsFields {
    val names = setOf("waitingReason")

    fun strip(body: String): String {
        if (names.none { "\"$it\"" in body }) return body
        return strip(Json.parseToJsonElement(body)).toString()
    }

    private fun strip(element: JsonElement): JsonElement = when (element) {
        is JsonObject -> JsonObject(element.filterKeys { it !in names }.mapValues { strip(it.value) })
        is JsonArray -> JsonArray(element.map(::strip))
        else -> element
    }
}
