package org.ktcs.adapters.vda5050.protocol

import com.networknt.schema.InputFormat
import com.networknt.schema.Schema
import com.networknt.schema.SchemaLocation
import com.networknt.schema.SchemaRegistry
import com.networknt.schema.dialect.Dialects

/** The messages a vehicle sends, each with its VDA 5050 2.0.0 JSON schema (in this module's resources). */
enum class IncomingTopic(val schemaFile: String) {
    STATE("state.schema.json"),
    CONNECTION("connection.schema.json"),
    VISUALIZATION("visualization.schema.json"),
    FACTSHEET("factsheet.schema.json"),
}

/**
 * Checks incoming messages against the VDA 5050 JSON schemas (networknt json-schema-validator, draft 2020-12). The
 * schemas load once, on first use, and are shared by every vehicle.
 */
object MessageValidator {
    private val registry by lazy { SchemaRegistry.withDefaultDialect(Dialects.getDraft202012()) }
    private val schemas = java.util.concurrent.ConcurrentHashMap<IncomingTopic, Schema>()

    /** What is wrong with [json] as a message on [topic]; empty when it is valid. */
    fun problems(topic: IncomingTopic, json: String): List<String> {
        val schema = schemas.computeIfAbsent(topic) {
            registry.getSchema(SchemaLocation.of("classpath:$SCHEMAS/${it.schemaFile}"))
        }
        return try {
            schema.validate(json, InputFormat.JSON).map { error ->
                "${error.instanceLocation.toString().ifEmpty { "$" }}: ${error.message}"
            }
        } catch (error: RuntimeException) {
            listOf("not JSON: ${error.message?.lineSequence()?.firstOrNull()}")
        }
    }

    private const val SCHEMAS = "org/ktcs/adapters/vda5050/schemas"
}
