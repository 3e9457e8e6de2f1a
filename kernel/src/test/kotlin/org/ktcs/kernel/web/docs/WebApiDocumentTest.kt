package org.ktcs.kernel.web.docs

import com.fasterxml.jackson.databind.JsonNode
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.nulls.shouldNotBeNull
import io.ktor.server.application.plugin
import io.ktor.server.routing.RoutingRoot
import io.ktor.server.testing.testApplication
import io.mockk.every
import io.mockk.mockk
import io.swagger.v3.parser.OpenAPIV3Parser
import io.swagger.v3.parser.core.models.ParseOptions
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.flow.flow
import org.ktcs.api.service.KernelServices
import org.ktcs.kernel.web.KernelVersion
import org.ktcs.kernel.web.webModule

/** kTCS's OpenAPI document is valid OpenAPI and describes exactly the routes the web server registers under /v1. */
class WebApiDocumentTest : FunSpec({
    val document = ApiDocument.current
    val registered by lazy { registeredV1Routes() }

    test("the document is valid OpenAPI 3 and needs no other file") {
        val result = OpenAPIV3Parser().readContents(document.yaml, null, ParseOptions().apply { isResolve = true })
        result.messages.shouldBeEmpty()
        result.openAPI.shouldNotBeNull()
        references(document.tree).filterNot { it.startsWith("#/") }.shouldBeEmpty()
    }

    test("it describes every route kTCS registers under /v1, and no other") {
        val documented = documentedOperations(document)
        withClue("routes kTCS serves that the document lacks") {
            (registered - documented).shouldBeEmpty()
        }
        withClue("documented routes kTCS does not serve") {
            (documented - registered).shouldBeEmpty()
        }
    }

    test("the route walk names routes as OpenAPI does: path parameters, nested routes, the WebSocket") {
        registered shouldContainAll setOf(
            Operation("GET", "/v1/vehicles/{NAME}"),
            Operation("PUT", "/v1/vehicles/{NAME}/commAdapter/enabled"),
            Operation("GET", "/v1/ws"),
            Operation("DELETE", "/v1/kernel"),
        )
    }
})

private fun documentedOperations(document: ApiDocument): Set<Operation> =
    document.tree.get("paths").properties()
        // openTCS documents its SSE named events as pseudo-paths `/sse::<event>`; they are no routes.
        .filterNot { (path, _) -> path.startsWith("/sse::") }
        .flatMap { (path, item) -> item.fieldNames().asSequence().map { Operation(it.uppercase(), "/v1$path") } }
        .toSet()

private fun references(node: JsonNode): List<String> =
    listOfNotNull(node.get("\$ref")?.asText()) + node.elements().asSequence().flatMap { references(it) }

private fun registeredV1Routes(): Set<Operation> {
    var operations = emptySet<Operation>()
    testApplication {
        application {
            webModule(KernelVersion("test"), quietServices())
            operations = plugin(RoutingRoot).operations().filter { it.path.startsWith("/v1/") }.toSet()
        }
        startApplication()
    }
    return operations
}

/** Services whose event stream stays open and silent: the route walk needs the web module, not a kernel. */
internal fun quietServices(): KernelServices = mockk(relaxed = true) {
    every { events() } returns flow { awaitCancellation() }
}
