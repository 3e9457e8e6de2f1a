package org.ktcs.e2e.docs

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.e2e.RepositoryRoot
import org.ktcs.kernel.config.ConfigFile
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.kernel.config.SettingsCatalogue
import java.nio.file.Files

/**
 * The shipped config file and the README's table are generated from, or checked against, the code's defaults: kTCS's
 * own settings and those of the extensions it ships (all on this module's class path, as on the launcher's).
 */
class ConfigDocumentationTest : FunSpec({
    val repositoryRoot = RepositoryRoot.path
    val settings = SettingsCatalogue.onClassPath()

    test("the settings of the shipped extensions are among them") {
        settings.map {
            it.key
        } shouldContainAll listOf("xml.orders.port", "loopback.timeFactor", "overview.vehicleTheme")
    }

    test("config/ktcs.conf lists every setting with its default and description") {
        val shipped = Files.readString(repositoryRoot.resolve("config/ktcs.conf"))
        shipped shouldBe ConfigFile.render()
    }

    test("the shipped config file, read as it is, yields the defaults") {
        val config = ConfigLoader().load(repositoryRoot.resolve("config/ktcs.conf"), emptyMap(), emptyList())
        settings.forEach { config.sourceOf(it) shouldBe "default" }
    }

    test("the README documents every setting with its default") {
        val readme = Files.readString(repositoryRoot.resolve("README.md"))
        settings.forEach { setting ->
            // A pipe inside a Markdown table cell must be escaped, even within backticks.
            readme shouldContain "| `${setting.key}` | `${setting.defaultText().replace("|", "\\|")}` |"
        }
    }
})
