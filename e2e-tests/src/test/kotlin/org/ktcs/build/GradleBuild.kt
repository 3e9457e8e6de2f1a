package org.ktcs.build

import java.nio.file.Path
import kotlin.io.path.exists
import kotlin.io.path.listDirectoryEntries
import kotlin.io.path.name
import kotlin.io.path.readText

/**
 * What [BuildFilesAgreeTest] needs from the Gradle mirror, read line by line with regexes: the modules that
 * [settings] includes, the version catalog ([catalogToml]), and each module's dependencies from its build file
 * ([buildFiles] by module directory) plus the convention plugins ([conventionPlugins] by plugin id) it applies.
 */
class GradleBuild(
    settings: String,
    catalogToml: String,
    private val buildFiles: Map<String, String>,
    private val conventionPlugins: Map<String, String>,
) {
    val modules: List<String> = includedModules(settings)

    val catalog = VersionCatalog(catalogToml)

    /** Included modules without a build file. */
    val missingBuildFiles: List<String> = (modules - buildFiles.keys).map { "$it/build.gradle.kts is missing" }

    /** The module's dependencies plus those of the convention plugins it applies; unknown names are kept as such. */
    fun dependencies(module: String): Set<Dependency> {
        val buildFile = code(buildFiles[module] ?: return emptySet())
        val conventions = PLUGIN_ID.findAll(buildFile).mapNotNull { conventionPlugins[it.groupValues[1]] }
        val scripts = listOf(buildFile) + conventions.map(::code)
        val declared = scripts.flatMap { script ->
            DECLARATION.findAll(script).mapNotNull { declaration ->
                val (configuration, argument) = declaration.destructured
                SCOPES[configuration]?.let { scope -> moduleOf(argument.trim())?.let { Dependency.of(it, scope) } }
            }
        }
        val appliesKotlin = scripts.any { script -> KOTLIN_PLUGIN.any { it in script } }
        // The Kotlin Gradle plugin adds kotlin-stdlib by itself; Maven declares it in the root pom.
        return (declared + listOfNotNull(KOTLIN_STDLIB.takeIf { appliesKotlin })).toSet()
    }

    /** `group:artifact`, `:module`, a placeholder naming what can't be resolved, or `null` for a BOM. */
    private fun moduleOf(argument: String): String? {
        // platform(...) mirrors a BOM import in <dependencyManagement>, not a <dependency>.
        if (argument.startsWith("platform(") || argument.startsWith("enforcedPlatform(")) return null
        fun match(regex: Regex) = regex.find(argument)?.groupValues?.get(1)
        return match(PROJECT)?.let { ":" + it.replace(':', '/') }
            ?: match(FIND_LIBRARY)?.let { catalog.libraries[it] ?: "$it (not in the catalog)" }
            ?: match(KOTLIN_MODULE)?.let { "org.jetbrains.kotlin:kotlin-$it" }
            ?: match(ACCESSOR)?.let { catalog.libraryFor(it) ?: "libs.$it (not in the catalog)" }
            ?: match(VARIANT)?.let { catalog.libraryFor(it) ?: "libs.$it (not in the catalog)" }
            ?: match(COORDINATES)
            ?: "$argument (unreadable)"
    }

    companion object {
        private val INCLUDE = Regex("""\binclude\(([^)]*)\)""")
        private val QUOTED = Regex(""""([^"]+)"""")
        private val PLUGIN_ID = Regex("""\bid\("([^"]+)"\)""")
        private val DECLARATION = Regex("""^\s*(\w+)\((.+)\)\s*$""", RegexOption.MULTILINE)
        private val PROJECT = Regex("""^project\(":([^"]+)"\)$""")
        private val FIND_LIBRARY = Regex("""^libs\.findLibrary\("([^"]+)"\)""")
        private val KOTLIN_MODULE = Regex("""^kotlin\("([^"]+)"\)$""")
        private val ACCESSOR = Regex("""^libs\.([\w.]+)$""")

        // variantOf(libs.x) { classifier("...") }: a library of the catalog with a classifier (a native jar).
        private val VARIANT = Regex("""^variantOf\(libs\.([\w.]+)\)""")
        private val COORDINATES = Regex("""^"([^":]+:[^":]+)(?::[^"]*)?"$""")
        private val LINE_COMMENT = Regex("""(^|\s)//.*$""")
        private val KOTLIN_PLUGIN = listOf("org.jetbrains.kotlin.jvm", "kotlin(\"jvm\")", "libs.plugins.kotlin.jvm")
        private val KOTLIN_STDLIB = Dependency("org.jetbrains.kotlin:kotlin-stdlib", "compile")

        /** Gradle configurations by the Maven scope they stand for. */
        private val SCOPES = mapOf(
            "api" to "compile",
            "implementation" to "compile",
            "compileOnly" to "provided",
            "runtimeOnly" to "runtime",
            "testImplementation" to "test",
            "testCompileOnly" to "test",
            "testRuntimeOnly" to "test",
        )

        /**
         * Reads settings, catalog, the build file of each top directory and of each included module (nested ones
         * such as `examples/tcp-vehicle-driver` too) and the buildSrc convention plugins.
         */
        fun read(root: Path): GradleBuild {
            val conventionDir = root.resolve("buildSrc/src/main/kotlin")
            val conventions = conventionDir.takeIf { it.exists() }?.listDirectoryEntries("*.gradle.kts").orEmpty()
            val settings = root.resolve("settings.gradle.kts").readText()
            val moduleDirectories = root.listDirectoryEntries().map { it.name } + includedModules(settings)
            return GradleBuild(
                settings,
                root.resolve("gradle/libs.versions.toml").readText(),
                moduleDirectories.distinct().map { it to root.resolve(it).resolve("build.gradle.kts") }
                    .filter { (_, file) -> file.exists() }
                    .associate { (module, file) -> module to file.readText() },
                conventions.associate { it.name.removeSuffix(".gradle.kts") to it.readText() },
            )
        }

        /** The included modules as directories: Gradle's `examples:tcp-vehicle-driver` is `examples/tcp-vehicle-driver`. */
        private fun includedModules(settings: String): List<String> =
            INCLUDE.findAll(code(settings)).flatMap { include ->
                QUOTED.findAll(include.groupValues[1]).map { it.groupValues[1].removePrefix(":").replace(':', '/') }
            }.toList()

        /** The script without `//` comments, so commented-out lines don't count. */
        private fun code(script: String): String = script.lines().joinToString("\n") { it.replace(LINE_COMMENT, "") }
    }
}
