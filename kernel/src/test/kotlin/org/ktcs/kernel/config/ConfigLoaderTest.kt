package org.ktcs.kernel.config

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.koin.dsl.module
import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.ConfigException
import org.ktcs.extension.config.intSetting
import org.ktcs.extension.config.positiveDoubleSetting
import java.nio.file.Files
import java.nio.file.Path

/** An extension declaring settings of its own, as the XML channels and the loopback driver do. */
private class SampleExtension(override val name: String = "sample") : KtcsExtension {
    val ordersPort = intSetting("sample.orders.port", 55555, 0..65535, "TCP port of the sample order channel.")
    val statusPort = intSetting("sample.status.port", 44444, 0..65535, "TCP port of the sample status channel.")
    val timeFactor = positiveDoubleSetting("sample.timeFactor", 1.0, "How much faster the samples run.")

    override val settings = listOf(ordersPort, statusPort, timeFactor)

    override fun module() = module {}
}

class ConfigLoaderTest : FunSpec({
    val sample = SampleExtension()
    val loader = ConfigLoader(SettingsCatalogue.of(listOf(sample)))

    fun configFile(vararg lines: String): Path =
        tempfile("ktcs", ".conf").toPath().also { Files.write(it, lines.toList()) }

    test("every setting has its default when nothing is configured") {
        val config = loader.load(null, emptyMap(), emptyList())

        config[KtcsSettings.webBindAddress] shouldBe "0.0.0.0"
        config[KtcsSettings.webPort] shouldBe 55200
        config[sample.ordersPort] shouldBe 55555
        config[sample.statusPort] shouldBe 44444
        config[sample.timeFactor] shouldBe 1.0
        config.sourceOf(KtcsSettings.webPort) shouldBe "default"
    }

    test("the file overrides defaults, the environment overrides the file, --set overrides both") {
        val file =
            configFile("# a comment", "", "web.port = 1000", "sample.orders.port=2000", "sample.status.port = 3000")
        val environment =
            mapOf("KTCS_SAMPLE_ORDERS_PORT" to "2001", "KTCS_SAMPLE_STATUS_PORT" to "3001", "PATH" to "/bin")

        val config = loader.load(file, environment, listOf("sample.status.port=3002"))

        config[KtcsSettings.webPort] shouldBe 1000
        config[sample.ordersPort] shouldBe 2001
        config[sample.statusPort] shouldBe 3002
        config.sourceOf(KtcsSettings.webPort) shouldBe "$file:3"
        config.sourceOf(sample.ordersPort) shouldBe "environment variable KTCS_SAMPLE_ORDERS_PORT"
        config.sourceOf(sample.statusPort) shouldBe "--set sample.status.port"
    }

    test("environment variable names are the key in capitals with underscores") {
        ConfigLoader.environmentName("web.bindAddress") shouldBe "KTCS_WEB_BINDADDRESS"
        loader.load(
            null,
            mapOf("KTCS_SAMPLE_TIMEFACTOR" to "2.5"),
            emptyList(),
        )[sample.timeFactor] shouldBe
            2.5
    }

    test("kTCS's own settings can be read first, skipping those only an extension declares") {
        val file = configFile("sample.orders.port = 1", "web.port = 1000")
        val own = ConfigLoader(KtcsSettings.all).load(
            file,
            mapOf("KTCS_SAMPLE_TIMEFACTOR" to "2"),
            listOf("sample.status.port=2", "kernel.dataDirectory=elsewhere"),
            ignoreUnknown = true,
        )
        own[KtcsSettings.webPort] shouldBe 1000
        own[KtcsSettings.dataDirectory] shouldBe "elsewhere"
        shouldThrow<ConfigException> { ConfigLoader(KtcsSettings.all).load(file, emptyMap(), emptyList()) }
            .message shouldContain "unknown setting 'sample.orders.port'"
    }

    test("a key declared twice names both declarers") {
        shouldThrow<ExtensionException> { SettingsCatalogue.of(listOf(sample, SampleExtension("copy"))) }
            .message shouldBe
            "extension 'copy' declares the setting 'sample.orders.port', which extension 'sample' declares too"
        val clash = object : KtcsExtension {
            override val name = "clash"
            override val settings = listOf(KtcsSettings.webPort)
            override fun module() = module {}
        }
        shouldThrow<ExtensionException> { SettingsCatalogue.of(listOf(clash)) }
            .message shouldBe "extension 'clash' declares the setting 'web.port', which kTCS declares too"
    }

    context("rejects with a message naming the key") {
        test("an unknown key in the file, with its line") {
            val file = configFile("web.port = 1", "web.prot = 2")
            shouldThrow<ConfigException> { loader.load(file, emptyMap(), emptyList()) }
                .message shouldBe "$file:2: unknown setting 'web.prot' (did you mean 'web.port'?)"
        }
        test("an unknown key in --set, suggesting the right spelling") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("web.bindaddress=1.2.3.4")) }
                .message shouldBe
                "--set web.bindaddress=1.2.3.4: unknown setting 'web.bindaddress' (did you mean 'web.bindAddress'?)"
        }
        test("a misspelt key, suggesting the closest one") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("sample.order.port=1")) }
                .message shouldBe
                "--set sample.order.port=1: unknown setting 'sample.order.port' (did you mean 'sample.orders.port'?)"
        }
        test("an unknown KTCS_ environment variable") {
            shouldThrow<ConfigException> { loader.load(null, mapOf("KTCS_WEB_PROT" to "1"), emptyList()) }
                .message shouldContain "unknown environment variable KTCS_WEB_PROT"
        }
        test("the launcher's own variables are no settings and no error") {
            val config = loader.load(null, mapOf("KTCS_JVM_DEFAULTS" to "", "KTCS_CDS" to "off"), emptyList())
            config.sourceOf(KtcsSettings.webPort) shouldBe "default"
        }
        test("a port out of range") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("web.port=70000")) }
                .message shouldBe "--set web.port: bad value '70000' for web.port: must be between 0 and 65535"
        }
        test("a value of the wrong type") {
            shouldThrow<ConfigException> { loader.load(null, mapOf("KTCS_SAMPLE_ORDERS_PORT" to "many"), emptyList()) }
                .message shouldBe
                "environment variable KTCS_SAMPLE_ORDERS_PORT: bad value 'many' for sample.orders.port: expected a whole number"
        }
        test("a time factor that is not positive") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("sample.timeFactor=0")) }
                .message shouldContain "for sample.timeFactor: must be a positive number"
        }
        test("an enum value that does not exist, listing the valid ones") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("log.level=LOUD")) }
                .message shouldContain "expected one of ERROR, WARN, INFO, DEBUG, TRACE"
        }
        test("a line that is no assignment") {
            val file = configFile("web.port 1")
            shouldThrow<ConfigException> { loader.load(file, emptyMap(), emptyList()) }
                .message shouldBe "$file:1: expected 'key = value', found 'web.port 1'"
        }
        test("a --set without '='") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("web.port")) }
                .message shouldBe "--set 'web.port': expected key=value"
        }
        test("a missing config file") {
            shouldThrow<ConfigException> { loader.load(Path.of("no/such.conf"), emptyMap(), emptyList()) }
                .message shouldBe "config file no/such.conf does not exist"
        }
    }
})
