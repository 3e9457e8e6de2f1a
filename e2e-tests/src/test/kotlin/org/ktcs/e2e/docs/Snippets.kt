package org.ktcs.e2e.docs

import java.nio.file.Files
import java.nio.file.Path

/**
 * Code in the documentation that is copied from compiled sources. A page marks a fenced block with
 * `<!-- snippet: path/from/repository/root#region -->` on the line before; the source marks the region with a line
 * `// snippet:region` and a line `// end-snippet`. The block must equal the region's lines without the common
 * indentation.
 */
object Snippets {
    private val MARKER = Regex("""^<!--\s*snippet:\s*(\S+)#([\w-]+)\s*-->\s*$""")
    private val FENCE = Regex("""^```""")
    private val REGION_START = Regex("""^\s*//\s*snippet:([\w-]+)\s*$""")
    private val REGION_END = Regex("""^\s*//\s*end-snippet\s*$""")

    /** A marked block of [page]: the [source] file, its [region], the block's text and its line in the page. */
    data class Block(val page: String, val line: Int, val source: String, val region: String, val text: String)

    /** Every marked block in [markdown]; a marker without a fenced block right after it is a problem too. */
    fun blocks(page: String, markdown: String): Pair<List<Block>, List<String>> {
        val lines = markdown.lines()
        val blocks = mutableListOf<Block>()
        val problems = mutableListOf<String>()
        lines.forEachIndexed { index, line ->
            val marker = MARKER.find(line.trim()) ?: return@forEachIndexed
            val (source, region) = marker.destructured
            val open = index + 1
            if (open >= lines.size || !FENCE.containsMatchIn(lines[open])) {
                problems += "$page:${index + 1}: snippet marker $source#$region is not followed by a fenced block"
                return@forEachIndexed
            }
            val close = (open + 1 until lines.size).firstOrNull { FENCE.containsMatchIn(lines[it]) }
            if (close == null) {
                problems += "$page:${open + 1}: the fenced block of $source#$region is never closed"
                return@forEachIndexed
            }
            blocks += Block(page, index + 1, source, region, lines.subList(open + 1, close).joinToString("\n"))
        }
        return blocks to problems
    }

    /** The lines of [region] in [sourceText] without their common indentation, or `null` if it is not there. */
    fun region(sourceText: String, region: String): String? {
        val lines = sourceText.lines()
        val start = lines.indexOfFirst { REGION_START.find(it)?.groupValues?.get(1) == region }
        if (start < 0) return null
        val end = (start + 1 until lines.size).firstOrNull { REGION_END.matches(lines[it]) } ?: return null
        return lines.subList(start + 1, end).joinToString("\n").trimIndent()
    }

    /** What is wrong with the snippets of the pages in [pages], each named relative to [root]. */
    fun problems(root: Path, pages: List<Path>): List<String> = pages.flatMap { page ->
        val name = root.relativize(page).toString()
        val (blocks, problems) = blocks(name, Files.readString(page))
        problems + blocks.mapNotNull { check(root, it) }
    }

    private fun check(root: Path, block: Block): String? {
        val where = "${block.page}:${block.line}: ${block.source}#${block.region}"
        val source = root.resolve(block.source)
        if (!Files.isRegularFile(source)) return "$where: the file ${block.source} does not exist"
        val markers = "// snippet:${block.region} ... // end-snippet"
        val expected = region(Files.readString(source), block.region)
            ?: return "$where: ${block.source} has no region '${block.region}' ($markers)"
        if (expected == block.text) return null
        val expectedLines = expected.lines()
        val actualLines = block.text.lines()
        val first = (0 until maxOf(expectedLines.size, actualLines.size))
            .first { expectedLines.getOrNull(it) != actualLines.getOrNull(it) }
        return "$where: the block differs from the source at its line ${first + 1}: " +
            "source has '${expectedLines.getOrNull(
                first,
            ) ?: "<end>"}', page has '${actualLines.getOrNull(first) ?: "<end>"}'"
    }
}
