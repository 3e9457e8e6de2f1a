package org.ktcs.build

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import java.nio.file.Path
import kotlin.io.path.exists

/**
 * Maven builds kTCS; the Gradle files (settings.gradle.kts, gradle/libs.versions.toml, the build.gradle.kts files
 * and buildSrc's convention plugin) mirror it for Gradle users. Nothing runs Gradle here, so this test keeps the
 * mirror honest: same modules, same versions, same dependencies per module.
 */
class BuildFilesAgreeTest : FunSpec({
    context("this repository's Maven and Gradle builds") {
        test("include the same modules") {
            val (maven, gradle) = readBuilds()
            (compareModules(maven.modules, gradle.modules) + gradle.missingBuildFiles).shouldAgree()
        }

        test("use the same versions") {
            val (maven, gradle) = readBuilds()
            val versions = compareVersions(maven.dependencyVersions, gradle.catalog.versions)
            (maven.problems + gradle.catalog.problems + versions).shouldAgree()
        }

        test("declare the same dependencies in every module") {
            val (maven, gradle) = readBuilds()
            maven.modules.flatMap { compareDependencies(it, maven.dependencies(it), gradle.dependencies(it)) }
                .shouldAgree()
        }
    }

    context("the comparison reports drift") {
        val build = TwoModuleBuild()

        test("a build in agreement has no differences") {
            build.differences().shouldBeEmpty()
        }

        test("a module that settings.gradle.kts does not include") {
            build.copy(settings = """include("core")""").differences() shouldBe
                listOf("module app is in pom.xml <modules> but not included in settings.gradle.kts")
        }

        test("a catalog version that differs from the pom property") {
            build.copy(catalog = build.catalog.replace("ktor = \"3.5.1\"", "ktor = \"3.5.2\"")).differences() shouldBe
                listOf("version ktor: pom.xml has ktor.version = 3.5.1, libs.versions.toml has ktor = 3.5.2")
        }

        test("a catalog version that no pom dependency uses") {
            build.copy(catalog = build.catalog.replace("[libraries]", "jgrapht = \"1.5.3\"\n[libraries]"))
                .differences() shouldBe
                listOf(
                    "version jgrapht: libs.versions.toml has jgrapht = 1.5.3, but no pom.xml dependency uses jgrapht.version",
                )
        }

        test("a pom dependency version that the catalog lacks") {
            build.copy(catalog = build.catalog.replace("kotest = \"6.2.4\"", "")).differences() shouldBe listOf(
                "libs.versions.toml: [libraries] kotest-runner-junit5 refers to the unknown version 'kotest'",
                "version kotest: pom.xml has kotest.version = 6.2.4, libs.versions.toml has no kotest",
            )
        }

        test("literal versions on either side") {
            val literalPom = build.rootPom.replace($$"${kotest.version}", "6.2.4")
            val inlineCatalog = build.catalog.replace("version.ref = \"kotest\"", "version = \"6.2.4\"")
            build.copy(rootPom = literalPom, catalog = inlineCatalog).differences() shouldBe listOf(
                "pom.xml gives io.kotest:kotest-runner-junit5-jvm the literal version 6.2.4: use a property in the " +
                    "root pom, as libs.versions.toml uses a version.ref",
                "libs.versions.toml: [libraries] kotest-runner-junit5 needs a version.ref, so that its version is compared",
                "version kotest: libs.versions.toml has kotest = 6.2.4, but no pom.xml dependency uses kotest.version",
            )
        }

        test("a dependency that only the pom declares") {
            build.copy(appBuild = build.appBuild.replace("api(libs.ktor.server.core)", "")).differences() shouldBe
                listOf("app: io.ktor:ktor-server-core (compile) is in pom.xml but not in build.gradle.kts")
        }

        test("a dependency that only build.gradle.kts declares, or names wrongly") {
            val extra = "testRuntimeOnly(\"io.mockk:mockk:1.14.11\")\nimplementation(libs.ktor.server.cio)\n}"
            build.copy(appBuild = build.appBuild.trimEnd().removeSuffix("}") + extra).differences() shouldBe listOf(
                "app: io.mockk:mockk (test) is in build.gradle.kts but not in pom.xml",
                "app: libs.ktor.server.cio (not in the catalog) (compile) is in build.gradle.kts but not in pom.xml",
            )
        }

        test("a dependency in another scope") {
            val appBuild = build.appBuild.replace(
                "testImplementation(libs.ktor.server.test",
                "runtimeOnly(libs.ktor.server.test",
            )
            build.copy(appBuild = appBuild).differences() shouldBe
                listOf("app: io.ktor:ktor-server-test-host is test in pom.xml but runtime in build.gradle.kts")
        }

        test("a root pom dependency that the convention plugin lacks") {
            build.copy(conventions = build.conventions.replace("testImplementation", "// testImplementation"))
                .differences() shouldBe listOf(
                "core: io.kotest:kotest-runner-junit5 (test) is in pom.xml but not in build.gradle.kts",
                "app: io.kotest:kotest-runner-junit5 (test) is in pom.xml but not in build.gradle.kts",
            )
        }
    }
})

private fun readBuilds(): Pair<MavenBuild, GradleBuild> {
    val root = repositoryRoot()
    return MavenBuild.read(root) to GradleBuild.read(root)
}

/** Set by e2e-tests/pom.xml (and build.gradle.kts); otherwise the nearest directory with settings.gradle.kts. */
internal fun repositoryRoot(): Path =
    System.getProperty("ktcs.repositoryRoot")?.takeIf { it.isNotBlank() }?.let { Path.of(it) }
        ?: generateSequence(Path.of("").toAbsolutePath()) { it.parent }
            .firstOrNull { it.resolve("settings.gradle.kts").exists() }
        ?: error("Can't find the repository root: set -Dktcs.repositoryRoot or run inside the repository")

private fun List<String>.shouldAgree() =
    withClue("The Maven and Gradle builds differ:\n" + joinToString("\n")) { shouldBeEmpty() }
