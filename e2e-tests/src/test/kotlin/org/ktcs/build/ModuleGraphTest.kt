package org.ktcs.build

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe

/**
 * Extensions build on the contract (`api`, `extension-api`), not on the kernel: no module's main class path may reach
 * `kernel`, directly or through another module (tests may use it; `provided` counts: the code compiles against it).
 * The exception are [TOOLS]: command-line tools run beside kTCS that read plant-model files and drive a kernel from
 * outside (a simulator, a benchmark), which no extension depends on. The Gradle files mirror the poms
 * ([BuildFilesAgreeTest]), so checking the poms checks both builds.
 */
class ModuleGraphTest : FunSpec({
    test("no module but the kernel has the kernel on its main class path") {
        val build = MavenBuild.read(repositoryRoot())
        withClue("Modules whose main code may use the kernel; build them on extension-api instead:") {
            kernelOnMainClassPath(build).shouldBeEmpty()
        }
    }

    test("api stays free of Ktor, Koin and Jackson; extension-api builds on api alone among the modules") {
        val build = MavenBuild.read(repositoryRoot())
        build.dependencies("api").map { it.module }.filter { it.startsWith(":") || FRAMEWORKS.containsMatchIn(it) }
            .shouldBeEmpty()
        build.dependencies("extension-api").map { it.module }.filter { it.startsWith(":") } shouldBe listOf(":api")
    }

    context("the check reports") {
        val root = """
            <project><groupId>org.ktcs</groupId><artifactId>ktcs-parent</artifactId><version>1</version>
            <modules><module>kernel</module><module>spi</module><module>driver</module><module>panel</module></modules>
            </project>
        """.trimIndent()

        fun pom(artifact: String, vararg dependencies: Pair<String, String>) =
            "<project><artifactId>ktcs-$artifact</artifactId><dependencies>" +
                dependencies.joinToString("") { (on, scope) ->
                    "<dependency><groupId>org.ktcs</groupId><artifactId>ktcs-$on</artifactId><scope>$scope</scope>" +
                        "</dependency>"
                } + "</dependencies></project>"

        // A kernel on the SPI, an SPI module, a driver and a panel that uses the driver, with the given dependencies.
        fun build(driver: Array<Pair<String, String>>, panel: Pair<String, String>) = MavenBuild(
            root,
            mapOf(
                "kernel" to pom("kernel", "spi" to "compile"),
                "spi" to pom("spi"),
                "driver" to pom("driver", *driver),
                "panel" to pom("panel", panel),
            ),
        )

        test("a module that depends on the kernel directly or through another module") {
            kernelOnMainClassPath(build(arrayOf("kernel" to "compile"), "driver" to "runtime")) shouldBe
                listOf("driver -> :kernel", "panel -> :driver -> :kernel")
        }

        test("a module that compiles against the kernel as a provided dependency") {
            kernelOnMainClassPath(build(arrayOf("kernel" to "provided"), "spi" to "compile")) shouldBe
                listOf("driver -> :kernel")
        }

        test("nothing when the kernel is a test dependency only") {
            kernelOnMainClassPath(build(arrayOf("spi" to "compile", "kernel" to "test"), "driver" to "compile"))
                .shouldBeEmpty()
        }
    }
})

/** Each module (other than the kernel) whose compile or runtime dependencies reach the kernel, with the path. */
private fun kernelOnMainClassPath(
    build: MavenBuild,
): List<String> = build.modules.filter { it != KERNEL && it !in TOOLS }
    .mapNotNull { module -> pathToKernel(build, module, listOf(module))?.joinToString(" -> ") }

private fun pathToKernel(build: MavenBuild, module: String, path: List<String>): List<String>? =
    build.dependencies(module)
        .filter { it.scope == "compile" || it.scope == "runtime" || it.scope == "provided" }
        .map { it.module }
        .filter { it.startsWith(":") && it !in path }
        .firstNotNullOfOrNull { dependency ->
            if (dependency == ":$KERNEL") {
                path + dependency
            } else {
                pathToKernel(build, dependency.removePrefix(":"), path + dependency)
            }
        }

private const val KERNEL = "kernel"

private val TOOLS = setOf("vda5050-tools")

private val FRAMEWORKS = Regex("^(io\\.ktor|io\\.insert-koin|com\\.fasterxml\\.jackson)")
