package org.ktcs.kernel.config

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import java.nio.file.Files
import java.nio.file.Path

class ConfigLoaderTest : FunSpec({
    val loader = ConfigLoader()

    fun configFile(vararg lines: String): Path =
        Files.createTempFile("ktcs", ".conf").also { Files.write(it, lines.toList()) }

    test("every setting has its default when nothing is configured") {
        val config = loader.load(null, emptyMap(), emptyList())

        config[KtcsSettings.webBindAddress] shouldBe "0.0.0.0"
        config[KtcsSettings.webPort] shouldBe 55200
        config[KtcsSettings.xmlOrdersPort] shouldBe 55555
        config[KtcsSettings.xmlStatusPort] shouldBe 44444
        config[KtcsSettings.loopbackTimeFactor] shouldBe 1.0
        config.sourceOf(KtcsSettings.webPort) shouldBe "default"
    }

    test("the file overrides defaults, the environment overrides the file, --set overrides both") {
        val file = configFile("# a comment", "", "web.port = 1000", "xml.orders.port=2000", "xml.status.port = 3000")
        val environment = mapOf("KTCS_XML_ORDERS_PORT" to "2001", "KTCS_XML_STATUS_PORT" to "3001", "PATH" to "/bin")

        val config = loader.load(file, environment, listOf("xml.status.port=3002"))

        config[KtcsSettings.webPort] shouldBe 1000
        config[KtcsSettings.xmlOrdersPort] shouldBe 2001
        config[KtcsSettings.xmlStatusPort] shouldBe 3002
        config.sourceOf(KtcsSettings.webPort) shouldBe "$file:3"
        config.sourceOf(KtcsSettings.xmlOrdersPort) shouldBe "environment variable KTCS_XML_ORDERS_PORT"
        config.sourceOf(KtcsSettings.xmlStatusPort) shouldBe "--set xml.status.port"
    }

    test("environment variable names are the key in capitals with underscores") {
        ConfigLoader.environmentName("web.bindAddress") shouldBe "KTCS_WEB_BINDADDRESS"
        loader.load(
            null,
            mapOf("KTCS_LOOPBACK_TIMEFACTOR" to "2.5"),
            emptyList(),
        )[KtcsSettings.loopbackTimeFactor] shouldBe
            2.5
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
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("xml.order.port=1")) }
                .message shouldBe
                "--set xml.order.port=1: unknown setting 'xml.order.port' (did you mean 'xml.orders.port'?)"
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
            shouldThrow<ConfigException> { loader.load(null, mapOf("KTCS_XML_ORDERS_PORT" to "many"), emptyList()) }
                .message shouldBe
                "environment variable KTCS_XML_ORDERS_PORT: bad value 'many' for xml.orders.port: expected a whole number"
        }
        test("a time factor that is not positive") {
            shouldThrow<ConfigException> { loader.load(null, emptyMap(), listOf("loopback.timeFactor=0")) }
                .message shouldContain "for loopback.timeFactor: must be a positive number"
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
