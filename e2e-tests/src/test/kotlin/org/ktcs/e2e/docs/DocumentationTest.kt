package org.ktcs.e2e.docs

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveAtLeastSize
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.TransportOrderState
import org.ktcs.e2e.RepositoryRoot
import org.ktcs.kernel.app.ConfigReference
import org.ktcs.kernel.orders.TransportOrderTransitions
import java.nio.file.Files
import java.nio.file.Path
import kotlin.io.path.extension
import kotlin.io.path.listDirectoryEntries

/** The developer's guide is true: its code is the compiled examples', its tables and diagrams the code's. */
class DocumentationTest : FunSpec({
    val root = RepositoryRoot.path
    val pages = root.resolve("docs").listDirectoryEntries().filter { it.extension == "md" }.sorted()
    val guide = Files.readString(root.resolve("docs/developers-guide.md"))

    test("every snippet in docs/ equals the region of the source file it names") {
        val snippets = pages.flatMap { Snippets.blocks(it.fileName.toString(), Files.readString(it)).first }
        snippets shouldHaveAtLeastSize 10
        withClue("Snippets that no longer match their sources:") { Snippets.problems(root, pages).shouldBeEmpty() }
    }

    test("docs/configuration.md is generated from the settings") {
        withClue("docs/configuration.md is out of date; regenerate it with `${ConfigReference.REGENERATE}`") {
            Files.readString(root.resolve("docs/configuration.md")) shouldBe ConfigReference.render()
        }
    }

    test("the guide's life-cycle diagram has exactly the transitions the kernel allows") {
        val allowed = TransportOrderState.entries.flatMap { from ->
            TransportOrderTransitions.successorsOf(from).map { to -> "$from --> $to" }
        }.toSet()
        mermaidEdges(guide) shouldBe allowed
    }

    context("the snippet check reports") {
        val sources = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-snippets")
        Files.createDirectories(sources.resolve("src"))
        Files.writeString(
            sources.resolve("src/Example.kt"),
            "fun main() {\n    // snippet:hello\n    println(\"hello\")\n    // end-snippet\n}\n",
        )
        fun problems(markdown: String): List<String> {
            val page = sources.resolve("page.md")
            Files.writeString(page, markdown)
            return Snippets.problems(sources, listOf(page))
        }

        test("nothing for a block equal to its region") {
            problems("<!-- snippet: src/Example.kt#hello -->\n```kotlin\nprintln(\"hello\")\n```\n").shouldBeEmpty()
        }

        test("a block that differs, with the first differing line") {
            problems("<!-- snippet: src/Example.kt#hello -->\n```kotlin\nprintln(\"hi\")\n```\n") shouldBe listOf(
                "page.md:1: src/Example.kt#hello: the block differs from the source at its line 1: " +
                    "source has 'println(\"hello\")', page has 'println(\"hi\")'",
            )
        }

        test("a missing file and a missing region") {
            problems(
                "<!-- snippet: src/Gone.kt#hello -->\n```\n```\n<!-- snippet: src/Example.kt#bye -->\n```\n```\n",
            ) shouldBe listOf(
                "page.md:1: src/Gone.kt#hello: the file src/Gone.kt does not exist",
                "page.md:4: src/Example.kt#bye: src/Example.kt has no region 'bye' (// snippet:bye ... // end-snippet)",
            )
        }

        test("a marker without a block") {
            problems("<!-- snippet: src/Example.kt#hello -->\ntext\n") shouldBe
                listOf("page.md:1: snippet marker src/Example.kt#hello is not followed by a fenced block")
        }
    }
})

/** The `A --> B` edges between states of the first mermaid `stateDiagram-v2` block in [markdown]. */
private fun mermaidEdges(markdown: String): Set<String> {
    val block = Regex("```mermaid\\s*\\n\\s*stateDiagram-v2\\n(.*?)```", RegexOption.DOT_MATCHES_ALL).find(markdown)
        ?: error("the guide has no mermaid stateDiagram-v2 block")
    return Regex("""^\s*(\w+)\s*-->\s*(\w+)""", RegexOption.MULTILINE).findAll(block.groupValues[1])
        .map { "${it.groupValues[1]} --> ${it.groupValues[2]}" }.toSet()
}
