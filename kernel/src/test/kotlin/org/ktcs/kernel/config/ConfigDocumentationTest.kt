package org.ktcs.kernel.config

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import java.nio.file.Files
import java.nio.file.Path

/** The shipped config file and the README's table are generated from, or checked against, the code's defaults. */
class ConfigDocumentationTest : FunSpec({
    val repositoryRoot = Path.of("..")

    test("config/ktcs.conf lists every setting with its default and description") {
        val shipped = Files.readString(repositoryRoot.resolve("config/ktcs.conf"))
        shipped shouldBe ConfigFile.render()
    }

    test("the shipped config file, read as it is, yields the defaults") {
        val config = ConfigLoader().load(repositoryRoot.resolve("config/ktcs.conf"), emptyMap(), emptyList())
        KtcsSettings.all.forEach { config.sourceOf(it) shouldBe "default" }
    }

    test("the README documents every setting with its default") {
        val readme = Files.readString(repositoryRoot.resolve("README.md"))
        KtcsSettings.all.forEach { setting ->
            // A pipe inside a Markdown table cell must be escaped, even within backticks.
            readme shouldContain "| `${setting.key}` | `${setting.defaultText().replace("|", "\\|")}` |"
        }
    }
})
