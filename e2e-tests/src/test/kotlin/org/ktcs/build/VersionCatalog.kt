package org.ktcs.build

/** gradle/libs.versions.toml, read line by line: every entry must fit on one line. */
class VersionCatalog(toml: String) {
    private class Entry(val section: String, val key: String, val value: String?)

    private val entries: List<Entry> = buildList {
        var section = ""
        for (line in toml.lines().map { it.replace(COMMENT, "").trim() }.filter { it.isNotEmpty() }) {
            val header = SECTION.matchEntire(line)
            if (header != null) {
                section = header.groupValues[1]
            } else {
                val entry = ENTRY.matchEntire(line)
                add(Entry(section, entry?.groupValues?.get(1) ?: line, entry?.groupValues?.get(2)))
            }
        }
    }

    val versions: Map<String, String> = valuesOf("versions").mapValues { (_, value) -> value.removeSurrounding("\"") }

    /** `group:artifact` by library alias. */
    val libraries: Map<String, String> = valuesOf("libraries").mapValues { (_, value) ->
        field("module", value)
            ?: field("group", value)?.let { group -> "$group:${field("name", value)}" }
            ?: value.removeSurrounding("\"").split(":").take(2).joinToString(":")
    }

    /** Lines that can't be read, and libraries or plugins whose version is not a `version.ref` into `[versions]`. */
    val problems: List<String> = entries.mapNotNull { entry ->
        val reference = entry.value?.let { field("version.ref", it) }
        val name = "[${entry.section}] ${entry.key}"
        when {
            entry.value == null -> "libs.versions.toml: can't read '${entry.key}' (keep each entry on one line)"
            entry.section != "libraries" && entry.section != "plugins" -> null
            reference == null -> "libs.versions.toml: $name needs a version.ref, so that its version is compared"
            reference !in versions -> "libs.versions.toml: $name refers to the unknown version '$reference'"
            else -> null
        }
    }

    private fun valuesOf(section: String): Map<String, String> =
        entries.filter { it.section == section }.mapNotNull { entry -> entry.value?.let { entry.key to it } }.toMap()

    /** The library that Gradle's type-safe accessor (`libs.ktor.server.core`) names. */
    fun libraryFor(accessor: String): String? =
        libraries.entries.firstOrNull { (alias, _) -> alias.replace('-', '.').replace('_', '.') == accessor }?.value

    private companion object {
        val COMMENT = Regex("""(^|\s)#.*$""")
        val SECTION = Regex("""^\[(\w+)]$""")
        val ENTRY = Regex("""^([\w.-]+)\s*=\s*(.+)$""")

        fun field(name: String, value: String): String? =
            Regex("""\b${Regex.escape(name)}\s*=\s*"([^"]*)"""").find(value)?.groupValues?.get(1)
    }
}
