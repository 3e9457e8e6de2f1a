package org.ktcs.overview

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.api.overview.OverviewPanel
import org.ktcs.extension.ExtensionException
import org.ktcs.extension.config.ConfigException
import org.ktcs.kernel.config.ConfigLoader
import java.net.URI
import java.net.http.HttpClient
import java.net.http.WebSocket
import java.nio.file.Path
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CompletionStage
import java.util.concurrent.TimeUnit

/** What the kernel application serves for the overview, over HTTP, without a browser. */
class OverviewServerTest : FunSpec({
    val ktcs = RunningKtcs(listOf("web.accessKey=secret"))
    afterSpec { ktcs.close() }

    test("the page is served at the root, outside the web API's access key") {
        val page = ktcs.get("/")
        page.statusCode() shouldBe 200
        page.headers().firstValue("Content-Type").get() shouldStartWith "text/html"
        page.body() shouldContain "<title>kTCS plant overview</title>"
        ktcs.get("/overview/app/main.js").headers().firstValue("Content-Type").get() shouldStartWith "text/javascript"
    }

    test("extensions.json lists the built-in panels and themes with their modules") {
        val entries = Json.parseToJsonElement(ktcs.get("/overview/extensions.json").body()).jsonArray.map {
            val entry = it.jsonObject
            listOf("kind", "name", "target", "module").joinToString(" ") { key -> entry[key]!!.jsonPrimitive.content }
        }
        entries shouldContainExactly listOf(
            "panel load-generator null /overview/extensions/load-generator/panel.js",
            "panel resource-allocation null /overview/extensions/resource-allocation/panel.js",
            "panel statistics null /overview/extensions/statistics/panel.js",
            "theme default-locations LOCATIONS /overview/extensions/default-locations/theme.js",
            "theme default-vehicles VEHICLES /overview/extensions/default-vehicles/theme.js",
            "theme high-contrast-locations LOCATIONS /overview/extensions/high-contrast-locations/theme.js",
            "theme high-contrast-vehicles VEHICLES /overview/extensions/high-contrast-vehicles/theme.js",
        )
        ktcs.get("/overview/extensions/statistics/panel.js").body() shouldContain "export default"
    }

    test("files outside a contribution's directory and unknown contributions are not found") {
        ktcs.get("/overview/extensions/statistics/%2e%2e/load-generator/panel.js").statusCode() shouldBe 404
        ktcs.get("/overview/extensions/nobody/panel.js").statusCode() shouldBe 404
        // Both targets exist and are JavaScript: only the refusal of `..` keeps them from being served.
        ktcs.get("/overview/app/%2e%2e/contributions/statistics/panel.js").statusCode() shouldBe 404
    }

    test("settings.json tells the page the chosen themes and that the API needs a key") {
        ktcs.get("/overview/settings.json").body() shouldBe
            """{"vehicleTheme":"default-vehicles","locationTheme":"default-locations","accessKeyRequired":true}"""
    }

    test("with an access key, the page's WebSocket passes it as a query parameter") {
        val messages = CompletableFuture<String>()
        val listener = object : WebSocket.Listener {
            override fun onText(socket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
                messages.complete(data.toString())
                return null
            }
        }
        val url = ktcs.baseUrl.replace("http://", "ws://") + "/v1/ws?accessKey=secret"
        val socket = HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(URI.create(url), listener)
            .get(10, TimeUnit.SECONDS)
        socket.sendText("""{"type":"subscribe","topics":["vehicles"]}""", true)
        messages.get(10, TimeUnit.SECONDS) shouldContain "\"type\":\"snapshot\""
        socket.abort()
    }

    test("the key as a query parameter opens only the WebSocket, not REST") {
        ktcs.get("/v1/vehicles?accessKey=secret").statusCode() shouldBe 403
    }

    test("an unknown theme name stops the start with a message listing the known themes") {
        val config = ConfigLoader().load(null, emptyMap(), listOf("overview.vehicleTheme=neon"))
        val contributions = Contributions(BuiltInContributions.all(javaClass.classLoader))
        shouldThrow<ConfigException> { ThemeSelection.from(config, contributions) }.message shouldBe
            "overview.vehicleTheme: unknown vehicles theme 'neon'; known: default-vehicles, high-contrast-vehicles"
    }

    test("an unknown theme name stops ./ktcs with that one line, not wrapped in Koin's definitions") {
        val err = java.io.ByteArrayOutputStream()
        // Like every start here: its data (state store, log file) in a temporary directory, not in the module's.
        val data = java.nio.file.Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-overview-data")
        val args = listOf(
            "--set",
            "web.port=0",
            "--set",
            "web.bindAddress=127.0.0.1",
            "--set",
            "kernel.dataDirectory=$data",
        )
            .plus(listOf("--set", "overview.vehicleTheme=neon"))
        val code = org.ktcs.kernel.app.Ktcs(
            java.io.PrintStream(java.io.OutputStream.nullOutputStream()),
            java.io.PrintStream(err, true),
            emptyMap(),
        )
            .run(args, awaitShutdown = {})
        data.toFile().deleteRecursively()
        code shouldBe 1
        err.toString().trim() shouldBe "ktcs: error: overview.vehicleTheme: unknown vehicles theme 'neon'; known: " +
            "default-vehicles, high-contrast-vehicles"
    }

    test("two contributions with the same name stop the start") {
        val loader = javaClass.classLoader
        val twice = List(2) { OverviewPanel("twin", "Twin", "org/example", classLoader = loader) }
        shouldThrow<ExtensionException> { Contributions(twice) }.message shouldContain
            "overview contributions share the name 'twin'"
    }
})
