package org.ktcs.kernel.app

import com.example.extensions.DispatcherFailingExtension
import com.example.extensions.MissingClassExtension
import com.example.extensions.WorkingExtension
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.koin.core.module.Module
import org.koin.dsl.module
import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import org.ktcs.kernel.config.ConfigLoader
import java.net.ConnectException
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse

class KernelApplicationTest : FunSpec({
    val localConfig = ConfigLoader().load(null, emptyMap(), listOf("web.bindAddress=127.0.0.1", "web.port=0"))
    val http = HttpClient.newHttpClient()

    fun get(url: String): HttpResponse<String> =
        http.send(HttpRequest.newBuilder(URI(url)).build(), HttpResponse.BodyHandlers.ofString())

    test("starts with the demo plant, announces itself in one line and serves the kernel version") {
        val application = KernelApplication(localConfig, PlantModelLoader.loadDemo(), emptyList())
        val ready = application.start()
        try {
            ready shouldStartWith "kTCS ready: model 'kTCS Demo' from demo plant (points=59 paths=75 locations=16 " +
                "locationTypes=4 blocks=2 vehicles=4); web API http://127.0.0.1:"
            val base = Regex("web API (http://\\S+)/v1").find(ready)!!.groupValues[1]
            val response = get("$base/v1/kernel/version")
            response.statusCode() shouldBe 200
            response.body() shouldContain "\"customizationName\":\"kTCS\""
        } finally {
            application.stop()
        }
    }

    test("stops serving when stopped") {
        val application = KernelApplication(localConfig, PlantModelLoader.loadDemo(), emptyList())
        val base = Regex("web API (http://\\S+)/v1").find(application.start())!!.groupValues[1]
        application.stop()
        shouldThrow<ConnectException> { get("$base/v1/kernel/version") }
    }

    test("names the extensions it loaded") {
        val extension = object : KtcsExtension {
            override val name = "test-extension"
            override fun module(): Module = module { }
        }
        val application = KernelApplication(localConfig, PlantModelLoader.loadDemo(), listOf(extension))
        try {
            application.start() shouldContain "extensions: test-extension"
        } finally {
            application.stop()
        }
    }

    test("an extension whose module fails stops the start with its name") {
        val broken = object : KtcsExtension {
            override val name = "broken-driver"
            override fun module(): Module = error("missing configuration")
        }
        val error = shouldThrow<ExtensionException> {
            KernelApplication(localConfig, PlantModelLoader.loadDemo(), listOf(broken)).start()
        }
        error.message shouldBe "extension 'broken-driver' failed to provide its module: missing configuration"
    }

    test("an extension whose definition fails at start is named, and nothing keeps running") {
        val port = java.net.ServerSocket(0).use { it.localPort }
        val config = ConfigLoader().load(null, emptyMap(), listOf("web.bindAddress=127.0.0.1", "web.port=$port"))
        val error = shouldThrow<ExtensionException> {
            KernelApplication(config, PlantModelLoader.loadDemo(), listOf(DispatcherFailingExtension())).start()
        }
        error.message shouldStartWith "extension 'failing-dispatcher' failed to start: "
        error.message shouldContain "no dispatcher licence"
        shouldThrow<ConnectException> { get("http://127.0.0.1:$port/v1/kernel/version") }
    }

    test("an extension whose module needs a missing class is named with the class") {
        val error = shouldThrow<ExtensionException> {
            KernelApplication(localConfig, PlantModelLoader.loadDemo(), listOf(MissingClassExtension())).start()
        }
        error.message shouldBe
            "extension 'missing-class' failed to provide its module: com/example/vendor/VendorProtocol"
    }

    test("the ready line says which jar an extension came from") {
        val jar = java.nio.file.Path.of("extensions", "working.jar")
        val application =
            KernelApplication(localConfig, PlantModelLoader.loadDemo(), listOf(WorkingExtension()), { jar })
        try {
            application.start() shouldContain "extensions: working (from $jar)"
        } finally {
            application.stop()
        }
    }
})
