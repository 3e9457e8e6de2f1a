package org.ktcs.kernel.web.v1

import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive

/**
 * openTCS's golden JSON samples (`*.approved.txt`, copied under `fixtures/opentcs/web-api/v1/`) and a JSON comparison
 * that ignores property order, as `shouldEqualJson` does.
 */
object GoldenJson {
    private val pretty = Json { prettyPrint = true }

    fun text(name: String): String =
        requireNotNull(javaClass.getResource("/fixtures/opentcs/web-api/v1/$name")) {
            "no golden file $name"
        }.readText()

    fun element(name: String): JsonElement = Json.parseToJsonElement(text(name))

    /** Both sides with their object keys sorted, pretty-printed, so a mismatch shows as a readable text diff. */
    infix fun String.shouldEqualJsonElement(expected: JsonElement) {
        canonical(Json.parseToJsonElement(this)) shouldBe canonical(expected)
    }

    private fun canonical(element: JsonElement): String = pretty.encodeToString(
        JsonElement.serializer(),
        sorted(element),
    )

    private fun sorted(element: JsonElement): JsonElement = when (element) {
        is JsonObject -> JsonObject(element.toSortedMap().mapValues { sorted(it.value) })
        is JsonArray -> JsonArray(element.map(::sorted))
        else -> element
    }
}

/**
 * This element with the value at [path] (dot-separated keys and array indexes, e.g. `driveOrders.0.state`) replaced by
 * [value]. Tests use it to state, one by one, where kTCS deliberately writes something else than a golden sample.
 */
fun JsonElement.with(path: String, value: JsonElement): JsonElement = replaced(path.split('.'), value)

fun JsonElement.with(path: String, value: String?): JsonElement = with(path, value?.let(::JsonPrimitive) ?: JsonNull)

fun JsonElement.with(path: String, value: Number): JsonElement = with(path, JsonPrimitive(value))

/** This SSE payload with [patch] applied to `currentObjectState` and `previousObjectState`. */
fun JsonElement.inBothStates(patch: JsonElement.(state: String) -> JsonElement): JsonElement =
    patch("currentObjectState").patch("previousObjectState")

/** This element without the array element at [path] (whose last part is an index). */
fun JsonElement.without(path: String): JsonElement {
    val parts = path.split('.')
    val index = parts.last().toInt()
    val array = at(parts.dropLast(1)) as JsonArray
    return replaced(parts.dropLast(1), JsonArray(array.filterIndexed { i, _ -> i != index }))
}

private fun JsonElement.at(parts: List<String>): JsonElement = parts.fold(this) { element, part ->
    when (element) {
        is JsonObject -> element.getValue(part)
        is JsonArray -> element[part.toInt()]
        else -> error("no '$part' in $element")
    }
}

private fun JsonElement.replaced(parts: List<String>, value: JsonElement): JsonElement {
    if (parts.isEmpty()) return value
    val head = parts.first()
    return when (this) {
        is JsonObject -> JsonObject(this + (head to getValue(head).replaced(parts.drop(1), value)))
        is JsonArray -> JsonArray(mapIndexed { i, e -> if (i == head.toInt()) e.replaced(parts.drop(1), value) else e })
        else -> error("no '$head' in $this")
    }
}
