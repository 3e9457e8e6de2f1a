package org.ktcs.kernel.web.docs

import com.fasterxml.jackson.databind.JsonNode
import com.fasterxml.jackson.databind.ObjectMapper
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory

/**
 * kTCS's OpenAPI document of web API v1 (`openapi.yaml` next to this class, one self-contained file), as it is
 * served: the YAML text, the same as JSON, and as a tree for pages generated from it.
 */
class ApiDocument private constructor(val yaml: String) {
    val tree: JsonNode = ObjectMapper(YAMLFactory()).readTree(yaml)
    val json: String = ObjectMapper().writerWithDefaultPrettyPrinter().writeValueAsString(tree)

    companion object {
        const val RESOURCE = "/org/ktcs/kernel/web/openapi.yaml"

        /** The document of this build; it is in the jar, so a missing one is a packaging bug. */
        val current: ApiDocument by lazy {
            val text = requireNotNull(ApiDocument::class.java.getResource(RESOURCE)) { "$RESOURCE is not in the jar" }
            ApiDocument(text.readText())
        }
    }
}
