package org.ktcs.kernel.app

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldStartWith
import org.ktcs.kernel.persistence.PlantModelFiles
import java.io.ByteArrayOutputStream
import java.io.PrintStream
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/** The `ktcs` command in-process: exit codes and what it prints. */
class KtcsTest : FunSpec({
    class Run(val exitCode: Int, val out: String, val err: String)

    fun ktcs(vararg args: String, environment: Map<String, String> = emptyMap()): Run {
        val out = ByteArrayOutputStream()
        val err = ByteArrayOutputStream()
        // A kTCS started here keeps nothing and writes no files into the module (state store, log file).
        val scratch = mapOf(
            "KTCS_PERSISTENCE_DURABILITY" to "OFF",
            "KTCS_KERNEL_DATADIRECTORY" to tempdir("ktcs-test-data").toPath().toString(),
        )
        val code = Ktcs(
            PrintStream(out, true),
            PrintStream(err, true),
            scratch + environment,
        ).run(args.toList(), awaitShutdown = {
        })
        return Run(code, out.toString(), err.toString())
    }

    fun fixture(resource: String): Path = Paths.get(KtcsTest::class.java.getResource(resource)!!.toURI())
    val samples = "/fixtures/opentcs/plant-models"

    context("model check") {
        test("prints the summary line of a valid model and exits 0") {
            val run = ktcs("model", "check", fixture("$samples/opentcs-7.5-head/Demo-01.xml").toString())
            run.exitCode shouldBe 0
            run.out.lines().first() shouldBe "points=59 paths=75 locations=16 locationTypes=4 blocks=2 vehicles=4"
        }

        test("prints warnings after the summary") {
            val run = ktcs("model", "check", fixture("$samples/test-samples-head/PlantModelV7.sample.xml").toString())
            run.exitCode shouldBe 0
            run.out.lines().drop(1).filter { it.isNotBlank() }.forEach { it shouldStartWith "warning: " }
        }

        test("lists every problem of a broken model and exits 1") {
            val broken = tempfile("broken", ".xml").toPath()
            Files.writeString(
                broken,
                Files.readString(fixture("$samples/opentcs-7.5-head/Demo-01.xml"))
                    .replace("destinationPoint=\"Point-0002\"", "destinationPoint=\"Point-9999\"")
                    .replace("length=\"5629\"", "length=\"-5629\""),
            )
            val run = ktcs("model", "check", broken.toString())
            run.exitCode shouldBe 1
            run.out shouldContain "error(s), the model cannot be loaded"
            run.out shouldContain "Point-9999"
            run.out shouldContain "length must be positive"
        }

        test("reports malformed XML with file, line and column") {
            val malformed = tempfile("malformed", ".xml").toPath()
            Files.writeString(
                malformed,
                "<?xml version=\"1.0\"?>\n<model version=\"7.0.0\" name=\"x\">\n<point name=\"A\"\n</model>",
            )
            val run = ktcs("model", "check", malformed.toString())
            run.exitCode shouldBe 1
            run.out shouldStartWith "error: $malformed:"
        }
    }

    test("model convert writes version 7.0.0 of an old model with the same content") {
        val output = tempdir("convert").toPath().resolve("Demo-01-7.xml")
        val input = fixture("$samples/opentcs-5.0/Demo-01.xml")

        val run = ktcs("model", "convert", input.toString(), output.toString())

        run.exitCode shouldBe 0
        Files.readString(output) shouldContain "<model version=\"7.0.0\" name=\"Demo-01\">"
        PlantModelFiles.read(output) shouldBe PlantModelFiles.read(input)
    }

    test("model convert refuses a missing file with a one-line error") {
        val run = ktcs("model", "convert", "no-such-model.xml", "out.xml")
        run.exitCode shouldBe 1
        run.err.trim().lines().size shouldBe 1
        run.err shouldContain "no-such-model.xml"
    }

    test("config prints every setting with its value and source") {
        val run = ktcs("config", "--set", "web.port=8080", environment = mapOf("KTCS_LOG_LEVEL" to "WARN"))
        run.exitCode shouldBe 0
        run.out.lines().shouldContainAll(
            "web.port = 8080  # --set web.port",
            "log.level = WARN  # environment variable KTCS_LOG_LEVEL",
            "web.bindAddress = 0.0.0.0  # default",
        )
    }

    test("run starts and stops the kernel, exit code 0") {
        ktcs("--set", "web.port=0", "--set", "web.bindAddress=127.0.0.1").exitCode shouldBe 0
    }

    test("a web port in use stops the start with one line naming the port, exit 1") {
        java.net.ServerSocket(0, 1, java.net.InetAddress.getByName("127.0.0.1")).use { taken ->
            val run = ktcs("--set", "web.port=${taken.localPort}", "--set", "web.bindAddress=127.0.0.1")
            run.exitCode shouldBe 1
            run.err.trim() shouldStartWith
                "ktcs: error: cannot listen on the configured address: web API port ${taken.localPort} on 127.0.0.1"
            run.err.lines().none { it.trimStart().startsWith("at ") } shouldBe true
        }
    }

    test("a missing model file is named without a Java exception") {
        val missing = tempdir("ktcs").toPath().resolve("plant.xml")
        val run = ktcs("--model", missing.toString())
        run.exitCode shouldBe 1
        run.err.trim() shouldBe "ktcs: error: $missing: cannot read the file: no such file"
    }

    test("usage mistakes exit 2 with the usage text") {
        val run = ktcs("--frobnicate")
        run.exitCode shouldBe 2
        run.err shouldStartWith "ktcs: unknown option '--frobnicate'"
        run.err shouldContain "Usage: ktcs"
    }

    test("configuration mistakes exit 1 naming the key") {
        val run = ktcs("--set", "web.port=-1")
        run.exitCode shouldBe 1
        run.err.trim() shouldBe "ktcs: error: --set web.port: bad value '-1' for web.port: must be between 0 and 65535"
    }

    test("a configured extensions directory that does not exist stops the start with one line, exit 1") {
        val missing = tempdir("ktcs").toPath().resolve("plugins")
        val run = ktcs("--set", "web.port=0", "--set", "extensions.directory=$missing")
        run.exitCode shouldBe 1
        run.err.trim() shouldBe
            "ktcs: error: extensions directory '$missing' (extensions.directory) does not exist"
    }

    test("a broken extension jar stops the start with one line naming it, exit 1") {
        val extensions = tempdir("ktcs-extensions").toPath()
        val broken = extensions.resolve("broken.jar")
        Files.writeString(broken, "not a jar")
        val run = ktcs("--set", "web.port=0", "--set", "extensions.directory=$extensions")
        run.exitCode shouldBe 1
        run.err shouldStartWith "ktcs: error: extension jar '$broken' cannot be read"
    }
})
