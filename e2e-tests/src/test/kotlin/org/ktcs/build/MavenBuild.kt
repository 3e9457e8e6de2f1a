package org.ktcs.build

import org.w3c.dom.Element
import org.xml.sax.InputSource
import java.io.StringReader
import java.nio.file.Path
import javax.xml.parsers.DocumentBuilderFactory
import kotlin.io.path.readText

/**
 * What [BuildFilesAgreeTest] needs from the Maven reactor: its modules, the versions its dependencies use and each
 * module's dependencies, read from the root [rootPom] and the [modulePomXml] by module directory.
 */
class MavenBuild(rootPom: String, modulePomXml: Map<String, String>) {
    private val root = parseXml(rootPom)
    private val modulePoms: Map<String, Element> = modulePomXml.mapValues { (_, pom) -> parseXml(pom) }
    private val rootProperties = properties(root) + ("project.version" to root.text("version").orEmpty())

    val modules: List<String> = root.child("modules")?.children("module").orEmpty().map { it.textContent.trim() }

    /** Maps `org.ktcs:ktcs-kernel` to `:kernel`, the name Gradle's `project(":kernel")` uses. */
    private val projectPaths: Map<String, String> = modulePoms.mapNotNull { (module, pom) ->
        val groupId = pom.text("groupId") ?: root.text("groupId")
        pom.text("artifactId")?.let { "$groupId:$it" to ":$module" }
    }.toMap()

    private val allPoms: Map<String, Element> =
        mapOf("pom.xml" to root) + modulePoms.mapKeys { (module, _) -> "$module/pom.xml" }

    /** The version properties that any `<dependency>` (managed, direct or of a plugin) refers to, with values. */
    val dependencyVersions: Map<String, String> = allPoms.values.flatMap { pom ->
        pom.dependencyVersions().mapNotNull { (_, version) -> propertyName(version)?.let { it to pom } }
    }.filter { (property, _) -> property != "project.version" }
        .associate { (property, pom) -> property to (resolve(property, pom) ?: "<undefined property>") }

    /** Dependency versions that are neither a property nor `${project.version}`, so the catalog can't mirror them. */
    val problems: List<String> = allPoms.flatMap { (file, pom) ->
        val literal = pom.dependencyVersions().filter { (_, version) -> propertyName(version) == null }
        literal.map { (coordinates, version) ->
            "$file gives $coordinates the literal version $version: use a property in the root pom, as " +
                "libs.versions.toml uses a version.ref"
        }
    }

    /** The module's dependencies plus those every module inherits from the root pom. */
    fun dependencies(module: String): Set<Dependency> {
        val pom = modulePoms[module] ?: return emptySet()
        return (root.directDependencies() + pom.directDependencies()).toSet()
    }

    private fun Element.directDependencies(): List<Dependency> =
        child("dependencies")?.children("dependency").orEmpty().map { dependency ->
            val coordinates = "${dependency.text("groupId")}:${dependency.text("artifactId")}"
            Dependency.of(projectPaths[coordinates] ?: coordinates, dependency.text("scope") ?: "compile")
        }

    /** The property's value with nested `${...}` references resolved, or `null` if one is undefined. */
    private fun resolve(property: String, pom: Element): String? {
        val properties = rootProperties + properties(pom)
        var value = properties[property] ?: return null
        repeat(10) {
            val reference = PROPERTY_REFERENCE.find(value) ?: return value
            value = value.replaceRange(reference.range, properties[reference.groupValues[1]] ?: return null)
        }
        return value
    }

    companion object {
        private val PROPERTY_REFERENCE = Regex("""\$\{([^}]+)}""")

        /** Reads the root pom and the pom of each module it lists. */
        fun read(root: Path): MavenBuild {
            val rootPom = root.resolve("pom.xml").readText()
            val modules = MavenBuild(rootPom, emptyMap()).modules
            return MavenBuild(rootPom, modules.associateWith { root.resolve(it).resolve("pom.xml").readText() })
        }

        private fun propertyName(version: String): String? =
            PROPERTY_REFERENCE.matchEntire(version)?.groupValues?.get(1)
    }
}

private fun parseXml(xml: String): Element =
    DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(InputSource(StringReader(xml))).documentElement

private fun Element.children(name: String): List<Element> =
    (0 until childNodes.length).map { childNodes.item(it) }.filterIsInstance<Element>().filter { it.tagName == name }

private fun Element.child(name: String): Element? = children(name).firstOrNull()

private fun Element.text(name: String): String? = child(name)?.textContent?.trim()

private fun properties(project: Element): Map<String, String> =
    project.child("properties")?.let { properties ->
        (0 until properties.childNodes.length).map { properties.childNodes.item(it) }
            .filterIsInstance<Element>().associate { it.tagName to it.textContent.trim() }
    }.orEmpty()

/** `groupId:artifactId` to version of every `<dependency>` in this pom that states a version. */
private fun Element.dependencyVersions(): List<Pair<String, String>> {
    val dependencies = getElementsByTagName("dependency")
    return (0 until dependencies.length).map { dependencies.item(it) as Element }.mapNotNull { dependency ->
        dependency.text("version")?.let { "${dependency.text("groupId")}:${dependency.text("artifactId")}" to it }
    }
}
