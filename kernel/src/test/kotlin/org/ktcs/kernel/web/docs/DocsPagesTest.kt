package org.ktcs.kernel.web.docs

import com.fasterxml.jackson.databind.ObjectMapper
import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.string.shouldStartWith
import io.ktor.client.request.get
import io.ktor.client.request.header
import io.ktor.client.statement.bodyAsText
import io.ktor.http.HttpHeaders
import io.ktor.http.HttpStatusCode
import io.ktor.server.testing.ApplicationTestBuilder
import io.ktor.server.testing.testApplication
import org.ktcs.kernel.web.KernelVersion
import org.ktcs.kernel.web.WebOptions
import org.ktcs.kernel.web.webModule

/** The documentation pages: Swagger UI from the webjar, the document, the WebSocket page; all local. */
class DocsPagesTest : FunSpec({
    fun docsTest(accessKey: String = "", block: suspend ApplicationTestBuilder.() -> Unit) = testApplication {
        application { webModule(KernelVersion("test"), quietServices(), WebOptions(accessKey = accessKey)) }
        block()
    }

    test("/docs/ is Swagger UI from the local webjar, loading the local document, with no link to the internet") {
        docsTest {
            val noRedirects = createClient { followRedirects = false }
            noRedirects.get("/docs").headers[HttpHeaders.Location] shouldBe "/docs/"

            val page = client.get("/docs/").bodyAsText()
            val assets = Regex("(?:src|href)=\"([^\"]+)\"").findAll(page).map { it.groupValues[1] }.toList()
            assets.filter { it.contains("//") } shouldBe emptyList()
            assets.filter { it.endsWith(".js") || it.endsWith(".css") }.forEach {
                val asset = client.get("/docs/$it")
                withClue(it) { asset.status shouldBe HttpStatusCode.OK }
                asset.bodyAsText().length shouldBeGreaterThan 0
            }
            client.get("/docs/swagger-ui-bundle.js").bodyAsText() shouldContain "SwaggerUIBundle"

            val initializer = client.get("/docs/swagger-initializer.js").bodyAsText()
            initializer shouldContain "url: \"openapi.yaml\""
            initializer shouldContain "validatorUrl: null"
            initializer shouldNotContain "petstore"
            client.get("/docs/openapi.yaml").bodyAsText() shouldBe ApiDocument.current.yaml
        }
    }

    test("the document is served at /v1 as YAML and as the same JSON, behind the access key; /docs/ is open") {
        docsTest(accessKey = "secret") {
            client.get("/v1/openapi.yaml").status shouldBe HttpStatusCode.Forbidden
            client.get("/docs/").status shouldBe HttpStatusCode.OK
            client.get("/docs/openapi.yaml").status shouldBe HttpStatusCode.OK

            val yaml = client.get("/v1/openapi.yaml") { header("X-Api-Access-Key", "secret") }
            yaml.bodyAsText() shouldStartWith "# kTCS web API v1"
            val json = client.get("/v1/openapi.json") { header("X-Api-Access-Key", "secret") }.bodyAsText()
            ObjectMapper().readTree(json) shouldBe ApiDocument.current.tree
        }
    }

    test("the WebSocket page shows every message and field of the protocol from the document") {
        docsTest {
            val page = client.get("/docs/websocket.html").bodyAsText()
            val schemas = ApiDocument.current.tree.get("components").get("schemas")
            listOf(
                "WsClientMessage",
                "WsSnapshot",
                "WsEvent",
                "WsMissed",
                "WsModelReplaced",
                "WsError",
            ).forEach { message ->
                page shouldContain "<h3 id=\"$message\">"
                schemas.get(message).get("properties").fieldNames().forEach { page shouldContain "<code>$it</code>" }
            }
            page shouldContain "<ol><li>The client subscribes"
            page shouldNotContain "`"
        }
    }
})
