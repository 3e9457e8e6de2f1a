package org.ktcs.kernel.web.contract

import com.fasterxml.jackson.databind.JsonNode
import com.fasterxml.jackson.databind.ObjectMapper
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory
import com.networknt.schema.InputFormat
import com.networknt.schema.Schema
import com.networknt.schema.SchemaLocation
import com.networknt.schema.SchemaRegistry
import com.networknt.schema.dialect.Dialects
import java.net.URI
import java.util.concurrent.ConcurrentHashMap

/**
 * One OpenAPI 3.0 document on the class path ([root], e.g. `fixtures/.../openapi.yaml`), possibly split into files as
 * openTCS's is. Finds the operation a request hit and validates response bodies against the operation's schema with
 * the networknt JSON Schema validator (OpenAPI 3.0 dialect, so `nullable` works); `$ref`s across files resolve as
 * the document's own relative references.
 */
class OpenApiContract(val name: String, private val root: String) {
    private val yaml = ObjectMapper(YAMLFactory())
    private val registry = SchemaRegistry.withDefaultDialect(Dialects.getOpenApi30())
    private val schemas = ConcurrentHashMap<String, Schema>()
    private val files = ConcurrentHashMap<String, JsonNode>()
    private val paths: Map<String, PathItem> = read(root).required("paths").properties().associate { (template, item) ->
        template to pathItem(template, item)
    }

    /** One violation: [where] (contract and operation), the JSON [pointer] into the body if the body is wrong, what. */
    data class Violation(val where: String, val pointer: String?, val message: String) {
        override fun toString() = when (pointer) {
            null -> "$where $message"
            else -> "$where: ${pointer.ifEmpty { "/" }} $message"
        }
    }

    /** Where a path item really is: openTCS's root document points into its `paths` files. */
    private data class PathItem(val file: String, val pointer: String, val node: JsonNode)

    private fun pathItem(template: String, item: JsonNode): PathItem {
        val ref = item.get("\$ref")?.asText() ?: return PathItem(root, "/paths/${escape(template)}", item)
        val file = resolve(root, ref.substringBefore('#'))
        val pointer = ref.substringAfter('#')
        return PathItem(file, pointer, read(file).at(pointer))
    }

    /** The template of the path (relative to the server URL `/v1`) that [path] matches, preferring literal segments. */
    fun template(method: String, path: String): String? = paths.keys
        .filter { matches(it, path) && paths.getValue(it).node.has(method.lowercase()) }
        .maxByOrNull { template -> template.split('/').count { !it.startsWith("{") } }

    /** Whether this document describes [status] for the operation; `default` counts. */
    fun describes(method: String, template: String, status: Int): Boolean = responseOf(method, template, status) != null

    /**
     * The violations of a response: its status is not described, or its body does not match the described content.
     * Each names the operation and, for schema violations, the JSON pointer into the body.
     */
    fun violations(method: String, template: String, status: Int, contentType: String?, body: String): List<Violation> {
        val operation = "$name: ${method.uppercase()} $template -> $status"
        val response =
            responseOf(method, template, status) ?: return listOf(Violation(operation, null, "is not described"))
        val content = response.node.get("content")
        if (content == null || content.isEmpty) {
            val unexpected = body.takeIf { it.isNotEmpty() } ?: return emptyList()
            return listOf(Violation(operation, null, "describes no body, but got: ${unexpected.take(200)}"))
        }
        if (!content.has("application/json")) return emptyList()
        if (contentType?.startsWith("application/json") != true) {
            return listOf(Violation(operation, null, "expects application/json, got content type $contentType"))
        }
        return violationsOf(response.file, "${response.pointer}/content/application~1json/schema", body, operation)
    }

    /** The violations of [json] against the schema at [pointer] (`/components/schemas/X`) of [file] (default: root). */
    fun violationsOf(file: String = root, pointer: String, json: String, where: String = name): List<Violation> {
        val schema = schemas.computeIfAbsent("$file#$pointer") {
            registry.getSchema(SchemaLocation.of("classpath:$file#$pointer"))
        }
        return schema.validate(json, InputFormat.JSON).map {
            Violation(
                where,
                it.instanceLocation.toString(),
                "${it.message} (was ${it.instanceNode.toString().take(60)})",
            )
        }
    }

    private data class Response(val file: String, val pointer: String, val node: JsonNode)

    private fun responseOf(method: String, template: String, status: Int): Response? {
        val item = paths[template] ?: return null
        val responses = item.node.get(method.lowercase())?.get("responses") ?: return null
        val key = listOf(status.toString(), "default").firstOrNull { responses.has(it) } ?: return null
        val response = responses.get(key)
        val ref = response.get("\$ref")?.asText()
            ?: return Response(item.file, "${item.pointer}/${method.lowercase()}/responses/$key", response)
        require(ref.startsWith("#/")) { "only references within the file are supported for responses, got $ref" }
        return Response(item.file, ref.substringAfter('#'), read(item.file).at(ref.substringAfter('#')))
    }

    private fun read(file: String): JsonNode = files.computeIfAbsent(file) {
        yaml.readTree(requireNotNull(javaClass.classLoader.getResource(file)) { "$file is not on the test class path" })
    }

    private companion object {
        fun matches(template: String, path: String): Boolean {
            val expected = template.split('/')
            val actual = path.split('/')
            return expected.size == actual.size &&
                expected.zip(actual).all { (e, a) -> e == a || (e.startsWith("{") && a.isNotEmpty()) }
        }

        fun resolve(base: String, relative: String): String =
            URI("x:/$base").resolve(relative).path.removePrefix("/")

        fun escape(key: String) = key.replace("~", "~0").replace("/", "~1")

        fun JsonNode.required(field: String): JsonNode = get(field) ?: error("no '$field' in the OpenAPI document")
    }
}
