package org.ktcs.adapters.vda5050.protocol

import com.networknt.schema.Schema
import com.networknt.schema.SchemaLocation
import com.networknt.schema.SchemaRegistry
import com.networknt.schema.dialect.Dialects
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import tools.jackson.core.JacksonException
import tools.jackson.databind.JsonNode
import tools.jackson.databind.json.JsonMapper
import tools.jackson.databind.node.ObjectNode
import java.util.Optional
import java.util.concurrent.ConcurrentHashMap

/** The messages a vehicle sends, each with its VDA 5050 2.0.0 JSON schema (in this module's resources). */
enum class IncomingTopic(val schemaFile: String) {
    STATE("state.schema.json"),
    CONNECTION("connection.schema.json"),
    VISUALIZATION("visualization.schema.json"),
    FACTSHEET("factsheet.schema.json"),
}

/** An incoming message read and checked: the message as JSON, or what is wrong with it. */
sealed interface Checked {
    data class Valid(val json: JsonElement) : Checked

    data class Invalid(val problems: List<String>) : Checked
}

/**
 * Checks incoming messages against the VDA 5050 JSON schemas (networknt json-schema-validator, draft 2020-12). The
 * schemas load once, on first use, and are shared by every vehicle. A message is parsed once: the schema checks the
 * parsed tree, and the driver decodes the same tree.
 */
object MessageValidator {
    private val registry by lazy { SchemaRegistry.withDefaultDialect(Dialects.getDraft202012()) }
    private val schemas = ConcurrentHashMap<IncomingTopic, Schema>()
    private val mapper = JsonMapper()

    /** [payload] (UTF-8 JSON) read and checked as a message on [topic]. */
    fun check(topic: IncomingTopic, payload: ByteArray): Checked {
        val tree = try {
            read(payload)
        } catch (error: JacksonException) {
            return notJson(error)
        }
        val problems = schemaProblems(topic, tree)
        return if (problems.isEmpty()) Checked.Valid(tree.toKotlinx()) else Checked.Invalid(problems)
    }

    /** [payload] (UTF-8 JSON) as a tree; throws [JacksonException] if it is not JSON. */
    internal fun read(payload: ByteArray): JsonNode = mapper.readTree(payload)

    internal fun notJson(error: JacksonException) = Checked.Invalid(listOf("not JSON: ${error.originalMessage}"))

    /** What is wrong with [tree] as a message on [topic]; empty when it is valid. */
    internal fun schemaProblems(topic: IncomingTopic, tree: JsonNode): List<String> =
        problems(schema(topic).validate(tree))

    /**
     * What is wrong with the fields [tree] has as fields of a `state` message; empty when they are valid. The fields a
     * message must have are not asked for: the caller knows the message has them.
     */
    internal fun stateFieldProblems(tree: JsonNode): List<String> = problems(stateFields.validate(tree))

    private fun problems(errors: List<com.networknt.schema.Error>) = errors.map {
        "${it.instanceLocation.toString().ifEmpty { "$" }}: ${it.message}"
    }

    private val stateFields by lazy { registry.getSchema(schemaTree(IncomingTopic.STATE).apply { remove("required") }) }

    private val quickSchemas = ConcurrentHashMap<IncomingTopic, Optional<QuickSchema>>()

    /**
     * [topic]'s schema as a [QuickSchema], which checks the values of a message by their bytes and accepts only what
     * the schema does; null if the schema uses more than a quick schema knows.
     */
    internal fun quickSchema(topic: IncomingTopic): QuickSchema? =
        quickSchemas.computeIfAbsent(topic) { Optional.ofNullable(QuickSchema.of(schemaTree(it))) }.orElse(null)

    private fun schemaTree(topic: IncomingTopic): ObjectNode =
        javaClass.classLoader.getResourceAsStream("$SCHEMAS/${topic.schemaFile}")!!.use {
            mapper.readTree(it) as ObjectNode
        }

    /** What is wrong with [json] as a message on [topic]; empty when it is valid. */
    fun problems(topic: IncomingTopic, json: String): List<String> =
        (check(topic, json.toByteArray()) as? Checked.Invalid)?.problems.orEmpty()

    private fun schema(topic: IncomingTopic): Schema = schemas.computeIfAbsent(topic) {
        registry.getSchema(SchemaLocation.of("classpath:$SCHEMAS/${it.schemaFile}"))
    }

    /** [this] tree as kotlinx's, which the driver decodes its messages from. */
    internal fun JsonNode.toKotlinx(): JsonElement = when {
        isObject -> JsonObject(properties().associate { (key, value) -> key to value.toKotlinx() })
        isArray -> JsonArray(values().map { it.toKotlinx() })
        isString -> JsonPrimitive(stringValue())
        isNumber -> JsonPrimitive(numberValue())
        isBoolean -> JsonPrimitive(booleanValue())
        else -> JsonNull
    }

    private const val SCHEMAS = "org/ktcs/adapters/vda5050/schemas"
}
