package org.ktcs.examples.overview

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.nulls.shouldNotBeNull
import io.kotest.matchers.shouldBe
import org.koin.dsl.koinApplication
import org.ktcs.api.overview.OverviewContribution
import org.ktcs.api.overview.OverviewPanel
import org.ktcs.api.overview.OverviewTheme
import org.ktcs.api.overview.ThemeTarget
import org.ktcs.kernel.extension.Extensions
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit

/** The extension binds a panel and a vehicle theme whose ES modules are present, valid and behave. */
class OverviewExamplesTest : FunSpec({
    val contributions = koinApplication { modules(OverviewExamplesExtension().module()) }
        .koin.getAll<OverviewContribution>().associateBy { it.name }

    test("the extension is found through ServiceLoader") {
        Extensions.discover().map { it.name } shouldContain "overview-examples"
    }

    test("it binds the fleet-energy panel and the energy theme for vehicles") {
        contributions.keys shouldBe setOf("fleet-energy", "energy")
        (contributions.getValue("fleet-energy") as OverviewPanel).title shouldBe "Fleet energy"
        (contributions.getValue("energy") as OverviewTheme).target shouldBe ThemeTarget.VEHICLES
    }

    test("each entry module is on the class path the contribution names") {
        contributions.values.forEach { contribution ->
            contribution.classLoader.getResource("${contribution.resourceDirectory}/${contribution.entryModule}")
                .shouldNotBeNull()
        }
    }

    context("with Node.js").config(enabledOrReasonIf = Node.availability()) {
        val panel = Node.copyModules(contributions.getValue("fleet-energy"), "panel.js", "energy.js")
        val theme = Node.copyModules(contributions.getValue("energy"), "theme.js")

        test("every module is valid JavaScript") {
            listOf(panel.resolve("panel.js"), panel.resolve("energy.js"), theme.resolve("theme.js")).forEach {
                Node.run("--check", it.toString()).trim() shouldBe ""
            }
        }

        test("the theme colours vehicles by energy and labels them with it") {
            val script = """
                import theme from "${theme.resolve("theme.js").toUri()}";
                const thresholds = { energyLevelCritical: 30, energyLevelGood: 90 };
                const styles = [20, 50, 95].map((energyLevel) =>
                  theme.vehicleStyle({ name: "V1", energyLevel, paused: false, energyLevelThresholdSet: thresholds }));
                console.log(JSON.stringify(styles));
            """.trimIndent()
            Node.evaluate(script).trim() shouldBe
                """[{"fill":"#d32f2f","stroke":"#424242","label":"V1 20%"},""" +
                """{"fill":"#f9a825","stroke":"#424242","label":"V1 50%"},""" +
                """{"fill":"#2e7d32","stroke":"#424242","label":"V1 95%"}]"""
        }

        test("the panel lists vehicles by name with their energy and order") {
            val script = """
                import { energyRows } from "${panel.resolve("panel.js").toUri()}";
                const vehicles = new Map([
                  ["V2", { name: "V2", energyLevel: 25, transportOrder: "T-7" }],
                  ["V1", { name: "V1", energyLevel: 100, transportOrder: null }],
                ]);
                console.log(JSON.stringify(energyRows(vehicles)));
            """.trimIndent()
            Node.evaluate(script).trim() shouldBe """[["V1","100%","#2e7d32","–"],["V2","25%","#d32f2f","T-7"]]"""
        }
    }
})

/** Runs Node.js on copies of the modules; Node treats `.js` files as ES modules only next to a package.json. */
private object Node {
    fun availability(): io.kotest.core.test.EnabledOrReasonIf = {
        if (runCatching { run("--version") }.isSuccess) {
            io.kotest.core.test.Enabled.enabled
        } else {
            io.kotest.core.test.Enabled.disabled("node is not installed, the JavaScript is not checked")
        }
    }

    fun copyModules(contribution: OverviewContribution, vararg files: String): Path {
        val directory = Files.createTempDirectory(
            Path.of("target").toAbsolutePath(),
            "ktcs-overview-${contribution.name}",
        )
        Files.writeString(directory.resolve("package.json"), """{"type":"module"}""")
        files.forEach { file ->
            val resource = contribution.classLoader.getResourceAsStream("${contribution.resourceDirectory}/$file")
                .shouldNotBeNull()
            resource.use { Files.copy(it, directory.resolve(file)) }
        }
        return directory
    }

    fun evaluate(script: String): String = run("--input-type=module", "--eval", script)

    fun run(vararg args: String): String {
        val process = ProcessBuilder(listOf("node") + args).redirectErrorStream(true).start()
        val output = process.inputStream.bufferedReader().readText()
        check(process.waitFor(30, TimeUnit.SECONDS)) { "node did not finish" }
        check(process.exitValue() == 0) { "node ${args.first()} failed:\n$output" }
        return output
    }
}
