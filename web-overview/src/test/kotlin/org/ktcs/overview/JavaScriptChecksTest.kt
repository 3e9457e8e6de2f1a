package org.ktcs.overview

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import io.kotest.matchers.string.shouldContain
import org.opentest4j.TestAbortedException
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import kotlin.io.path.absolute
import kotlin.io.path.writeText

/**
 * The overview's JavaScript is type-checked (TypeScript's checkJs over its JSDoc types, `tsconfig.json`) and linted
 * (ESLint, `eslint.config.js`), with the tools `package.json` pins, fetched by `npm ci`. Users need none of it: the
 * overview serves its files as they are. Where Node is missing the checks are skipped with the reason, except in CI
 * (`CI=true`) or with `KTCS_REQUIRE_NODE=1`, where they fail.
 */
class JavaScriptChecksTest : FunSpec({
    val module = Path.of("").absolute()

    test("the overview's JavaScript passes the type check and the linter") {
        Npm.install(module)
        val check = Npm.run(module, "npm", "run", "--silent", "check")
        withClue("npm run check (in web-overview) found problems:\n${check.output}") { check.exitCode shouldBe 0 }
    }

    test("the overview's JavaScript unit checks pass (path geometry, node --test src/test/js)") {
        Npm.install(module)
        val run = Npm.run(module, "npm", "test", "--silent")
        withClue("npm test (in web-overview) failed:\n${run.output}") { run.exitCode shouldBe 0 }
        run.output shouldContain "# pass"
    }

    test("the type check finds a wrong type in a JSDoc-typed module") {
        Npm.install(module)
        val project = Files.createTempDirectory("ktcs-checkjs")
        project.resolve("broken.js").writeText(
            "/** @param {number} metres */\nexport function kilometres(metres) { return metres / 1000; }\n" +
                "kilometres('12 m');\n",
        )
        project.resolve("tsconfig.json").writeText(
            """{ "extends": "${module.resolve("tsconfig.json")}", "include": ["$project/*.js"] }""",
        )
        val tsc = module.resolve("node_modules/.bin/tsc").toString()
        val check = Npm.run(module, tsc, "-p", project.resolve("tsconfig.json").toString())
        check.exitCode shouldNotBe 0
        check.output shouldContain "broken.js(3,12): error TS2345"
    }
})

private object Npm {
    private val required = System.getenv("CI") == "true" || System.getenv("KTCS_REQUIRE_NODE") == "1"

    class Result(val exitCode: Int, val output: String)

    /** `npm ci` unless node_modules matches package-lock.json already; skips the test where Node is missing. */
    fun install(module: Path) {
        val marker = module.resolve("node_modules/.package-lock.json")
        val lock = module.resolve("package-lock.json")
        if (Files.exists(marker) && Files.getLastModifiedTime(marker) >= Files.getLastModifiedTime(lock)) return
        val result = runOrNull(module, "npm", "ci", "--no-audit", "--no-fund")
            ?: skip(
                "node and npm are not on the PATH: install Node.js 20+ to type-check and lint the overview's JavaScript",
            )
        if (result.exitCode != 0) skip("npm ci failed (is the npm registry reachable?):\n${result.output}")
    }

    fun run(module: Path, vararg command: String): Result = runOrNull(module, *command)
        ?: error("${command.first()} cannot be started")

    private fun runOrNull(module: Path, vararg command: String): Result? {
        val process = try {
            ProcessBuilder(*command).directory(module.toFile()).redirectErrorStream(true).start()
        } catch (_: java.io.IOException) {
            return null
        }
        val output = process.inputStream.bufferedReader().readText()
        check(process.waitFor(5, TimeUnit.MINUTES)) { "${command.joinToString(" ")} did not end within 5 minutes" }
        return Result(process.exitValue(), output)
    }

    private fun skip(reason: String): Nothing {
        check(!required) { "JavaScript checks required (CI=true or KTCS_REQUIRE_NODE=1), but $reason" }
        System.err.println("JavaScript checks skipped: $reason")
        throw TestAbortedException(reason)
    }
}
