package org.ktcs.xmlchannels.orders

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.HostClient
import org.ktcs.xmlchannels.HostSchemas
import org.ktcs.xmlchannels.HostSchemas.validate
import org.ktcs.xmlchannels.XmlTree
import org.ktcs.xmlchannels.sample
import org.ktcs.xmlchannels.testSettings
import org.ktcs.xmlchannels.withChannels
import java.nio.file.Files
import java.nio.file.Path

class OrderScriptTest : FunSpec({
    fun scriptsWith(vararg files: Pair<String, String>): Path = tempdir("ktcs-host").toPath().let { root ->
        Files.createDirectory(root.resolve("scripts")).also { scripts ->
            files.forEach { (name, text) -> Files.writeString(scripts.resolve(name), text) }
        }
    }

    suspend fun run(scripts: Path, vararg fileNames: String, services: FakeKernelServices = FakeKernelServices()) =
        withChannels(services, testSettings(scripts)) { channels ->
            val orders = fileNames.map {
                """<order xsi:type="transportScript" id="$it" fileName="$it" xmlns:xsi="$XSI"/>"""
            }
            HostClient.send(channels.ordersPort, orderSet(*orders.toTypedArray()))
        }.also { HostSchemas.response.validate(it) }

    test("with sequential dependencies each order of a script depends on the one before") {
        val services = FakeKernelServices()
        val script = sample("test.tcs").replace("sequentialDependencies=\"false\"", "sequentialDependencies=\"true\"")
        run(scriptsWith("chain.tcs" to script), "chain.tcs", services = services)

        services.created.map { it.dependencies } shouldBe listOf(emptySet(), setOf("TOrder-0001"))
    }

    test("once an order of a sequential script fails, the orders after it are not created") {
        val services = FakeKernelServices()
        val script = sample("test.tcs").replace("sequentialDependencies=\"false\"", "sequentialDependencies=\"true\"")
            .replace("TST11", "Nowhere")
        val receipt = run(scriptsWith("chain.tcs" to script), "chain.tcs", services = services)

        XmlTree.of(receipt).children.single().children.map { it.attributes["reason"] } shouldBe listOf(
            "unknown location 'Nowhere'",
            "an earlier order of this sequential script was not created",
        )
        services.created shouldBe emptyList()
    }

    test("only the base name of a script's file name counts, so no path leads out of the scripts directory") {
        val scripts = scriptsWith("test.tcs" to sample("test.tcs"))
        Files.writeString(scripts.resolveSibling("outside.tcs"), sample("test.tcs"))
        val receipt = run(scripts, "../outside.tcs", "/etc/../test.tcs", "..\\..\\test.tcs", "..")

        XmlTree.of(receipt).children.map { it.attributes["parsingSuccessful"] to it.attributes["reason"] } shouldBe
            listOf(
                "false" to "no script 'outside.tcs' in the scripts directory",
                "true" to null,
                "true" to null,
                "false" to "no script file name in '..'",
            )
    }

    test("a script that is not well-formed fails to parse and creates nothing") {
        val services = FakeKernelServices()
        val receipt = run(scriptsWith("broken.tcs" to "<tcsScriptFile><order>"), "broken.tcs", services = services)

        XmlTree.of(receipt).children.single().attributes["parsingSuccessful"] shouldBe "false"
        services.created shouldBe emptyList()
    }

    test("template.tcs is written on the first start, valid by the script schema, and kept afterwards") {
        val scripts = tempdir("ktcs-host").toPath().resolve("scripts")
        withChannels(settings = testSettings(scripts)) {}
        val template = scripts.resolve(ScriptFiles.TEMPLATE)
        HostSchemas.orderScript.validate(Files.readString(template))

        Files.writeString(template, "mine")
        withChannels(settings = testSettings(scripts)) {}
        Files.readString(template) shouldBe "mine"
    }
})
