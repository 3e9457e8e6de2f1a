package org.ktcs.kernel.web.docs

import com.fasterxml.jackson.databind.JsonNode

/**
 * The WebSocket protocol as a readable page, generated from the OpenAPI document: the description of `GET /ws`,
 * then each message of the `x-websocket` section with its fields, so page and schemas cannot disagree.
 */
internal object WebSocketPage {
    fun render(document: ApiDocument): String {
        val root = document.tree
        val section = root.required("x-websocket")
        val schemas = root.required("components").required("schemas")
        val description = root.required("paths").required("/ws").required("get").required("description").asText()
        return buildString {
            append(HEAD)
            append("<h1>kTCS WebSocket protocol v${section.required("protocolVersion").asInt()}</h1>\n")
            append("<p>Channel: <code>${escape(section.required("channel").asText())}</code> &middot; ")
            append("<a href=\"./\">the whole API</a> &middot; <a href=\"openapi.yaml\">openapi.yaml</a></p>\n")
            append(Markdown.toHtml(description))
            messages(section.required("publish"), schemas, "Client to server")
            messages(section.required("subscribe"), schemas, "Server to client")
            listOf("WsTopic", "WsTopicObject", "WsNotification").forEach { schema(it, schemas.required(it)) }
            append("</body></html>\n")
        }
    }

    private fun StringBuilder.messages(direction: JsonNode, schemas: JsonNode, heading: String) {
        append("<h2>${escape(heading)}: ${escape(direction.required("summary").asText())}</h2>\n")
        direction.required("messages").forEach { schema(it.asText(), schemas.required(it.asText())) }
    }

    private fun StringBuilder.schema(name: String, schema: JsonNode) {
        append("<h3 id=\"${escape(name)}\">${escape(name)}</h3>\n")
        schema.get("description")?.let { append("<p>${Markdown.inline(it.asText())}</p>\n") }
        schema.get("enum")?.let {
            append("<p>One of: ${it.joinToString { v -> "<code>${escape(v.asText())}</code>" }}</p>\n")
        }
        val properties = schema.get("properties") ?: return
        val required = schema.get("required")?.map { it.asText() }?.toSet().orEmpty()
        append("<table><tr><th>Field</th><th>Type</th><th>Required</th><th>Meaning</th></tr>\n")
        properties.properties().forEach { (field, property) ->
            append("<tr><td><code>${escape(field)}</code></td><td>${escape(typeOf(property))}</td>")
            append("<td>${if (field in required) "yes" else "no"}</td>")
            append("<td>${Markdown.inline(property.get("description")?.asText().orEmpty())}</td></tr>\n")
        }
        append("</table>\n")
    }

    private fun typeOf(property: JsonNode): String {
        val base = when {
            property.has("\$ref") -> property.get("\$ref").asText().substringAfterLast('/')
            property.has("allOf") -> property.get("allOf").joinToString(" & ") { typeOf(it) }
            property.get("type")?.asText() == "array" -> "array of ${typeOf(property.required("items"))}"
            else -> property.get("type")?.asText() ?: "any"
        }
        val values = property.get("enum")?.joinToString(", ", " (", ")") { it.asText() }.orEmpty()
        return base + values + if (property.get("nullable")?.asBoolean() == true) " or null" else ""
    }

    private const val HEAD = """<!DOCTYPE html>
<html lang="en"><head><meta charset="UTF-8"><title>kTCS WebSocket protocol</title>
<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.4}
table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top}
code{background:#f3f3f3;padding:0 .2em}</style></head><body>
"""
}

/** The little Markdown the document's descriptions use: paragraphs, numbered lists, `code`. */
internal object Markdown {
    fun toHtml(text: String): String = text.trim().split(Regex("\n\\s*\n")).joinToString("\n") { block ->
        val items = block.split(Regex("\n(?=\\d+\\. )"))
        if (items.first().matches(Regex("(?s)\\d+\\. .*"))) {
            items.joinToString("", "<ol>", "</ol>") { "<li>${inline(it.substringAfter(". "))}</li>" }
        } else {
            "<p>${inline(block)}</p>"
        }
    }

    fun inline(text: String): String = escape(text).replace(Regex("`([^`]+)`"), "<code>$1</code>")
}

internal fun escape(text: String): String =
    text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")

private fun JsonNode.required(name: String): JsonNode =
    get(name) ?: error("the OpenAPI document has no '$name' where the WebSocket page expects it")
