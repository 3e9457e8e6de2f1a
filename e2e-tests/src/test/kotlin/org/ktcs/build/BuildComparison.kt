package org.ktcs.build

/**
 * A dependency as both builds can name it: `group:artifact` (or `:kernel` for a module of this build) and its scope,
 * in Maven's words (`compile`, `runtime`, `provided`, `test`).
 */
data class Dependency(val module: String, val scope: String) {
    companion object {
        /** Multiplatform libraries are `ktor-server-core-jvm` in Maven and `ktor-server-core` in Gradle. */
        fun of(module: String, scope: String) = Dependency(module.removeSuffix("-jvm"), scope)
    }
}

/** Differences between the root pom's `<modules>` and the projects settings.gradle.kts includes. */
fun compareModules(maven: List<String>, gradle: List<String>): List<String> =
    (maven - gradle.toSet()).map { "module $it is in pom.xml <modules> but not included in settings.gradle.kts" } +
        (gradle - maven.toSet()).map { "module $it is included in settings.gradle.kts but not in pom.xml <modules>" }

/**
 * Differences between the pom properties that dependency versions use ([maven], e.g. `ktor.version`) and the
 * catalog's `[versions]` ([catalog], e.g. `ktor`): each must have its counterpart, with the same value.
 */
fun compareVersions(maven: Map<String, String>, catalog: Map<String, String>): List<String> {
    val properties = maven.keys.associateBy { it.removeSuffix(".version") }
    return (properties.keys + catalog.keys).sorted().mapNotNull { key ->
        val property = properties[key]
        val mavenVersion = property?.let(maven::getValue)
        val gradleVersion = catalog[key]
        when {
            gradleVersion == null ->
                "version $key: pom.xml has $property = $mavenVersion, libs.versions.toml has no $key"

            property == null ->
                "version $key: libs.versions.toml has $key = $gradleVersion, but no pom.xml dependency uses $key.version"

            mavenVersion != gradleVersion ->
                "version $key: pom.xml has $property = $mavenVersion, libs.versions.toml has $key = $gradleVersion"

            else -> null
        }
    }
}

/** Differences between a module's dependencies in its pom.xml files and in its Gradle build files. */
fun compareDependencies(module: String, maven: Set<Dependency>, gradle: Set<Dependency>): List<String> {
    val mavenScopes = maven.groupBy({ it.module }, { it.scope })
    val gradleScopes = gradle.groupBy({ it.module }, { it.scope })
    return (mavenScopes.keys + gradleScopes.keys).sorted().mapNotNull { dependency ->
        val inMaven = mavenScopes[dependency]?.toSortedSet()?.joinToString("+")
        val inGradle = gradleScopes[dependency]?.toSortedSet()?.joinToString("+")
        when {
            inGradle == null -> "$module: $dependency ($inMaven) is in pom.xml but not in build.gradle.kts"
            inMaven == null -> "$module: $dependency ($inGradle) is in build.gradle.kts but not in pom.xml"
            inMaven != inGradle -> "$module: $dependency is $inMaven in pom.xml but $inGradle in build.gradle.kts"
            else -> null
        }
    }
}

/** Every difference between the two builds, and every problem met while reading them. */
fun buildDifferences(maven: MavenBuild, gradle: GradleBuild): List<String> =
    compareModules(maven.modules, gradle.modules) +
        gradle.missingBuildFiles + maven.problems + gradle.catalog.problems +
        compareVersions(maven.dependencyVersions, gradle.catalog.versions) +
        maven.modules.flatMap { compareDependencies(it, maven.dependencies(it), gradle.dependencies(it)) }
