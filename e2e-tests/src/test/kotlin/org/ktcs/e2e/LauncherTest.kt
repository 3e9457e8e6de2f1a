package org.ktcs.e2e

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import io.kotest.matchers.string.shouldStartWith
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import java.util.jar.JarFile
import java.util.zip.ZipEntry
import kotlin.time.Duration.Companion.seconds

/** `./ktcs` as the README tells a user to run it. */
class LauncherTest : FunSpec({
    // Any free ports: a test must not depend on the default ports being free on the machine.
    val local = listOf(
        "web.bindAddress=127.0.0.1",
        "web.port=0",
        "xml.bindAddress=127.0.0.1",
        "xml.orders.port=0",
        "xml.status.port=0",
    )
        .flatMap { listOf("--set", it) }
        .toTypedArray()

    test("starts with the demo plant, logs one ready line, serves, and exits 0 on SIGTERM") {
        KtcsProcess(*local).use { ktcs ->
            val ready = ktcs.awaitLine("kTCS ready")
            ready shouldContain
                "model 'kTCS Demo' from demo plant (points=59 paths=75 locations=16 locationTypes=4 blocks=2 vehicles=4)"
            val base = Regex("web API (http://\\S+)/v1").find(ready)!!.groupValues[1]
            val response = HttpClient.newHttpClient()
                .send(
                    HttpRequest.newBuilder(URI("$base/v1/kernel/version")).build(),
                    HttpResponse.BodyHandlers.ofString(),
                )
            response.statusCode() shouldBe 200

            ktcs.terminate() shouldBe 0
            ktcs.output().lines().filter { "kTCS ready" in it } shouldHaveSize 1
            ktcs.output().lines().filter { " ERROR " in it } shouldHaveSize 0
        }
    }

    test("DELETE /v1/kernel from this machine with the access key shuts kTCS down with exit code 0") {
        KtcsProcess(*local, "--set", "web.accessKey=stop-it").use { ktcs ->
            val base = Regex("web API (http://\\S+)/v1").find(ktcs.awaitLine("kTCS ready"))!!.groupValues[1]
            fun delete(key: String?) = HttpClient.newHttpClient().send(
                HttpRequest.newBuilder(URI("$base/v1/kernel")).DELETE()
                    .apply { key?.let { header("X-Api-Access-Key", it) } }.build(),
                HttpResponse.BodyHandlers.ofString(),
            ).statusCode()
            delete(null) shouldBe 403
            delete("stop-it") shouldBe 200
            ktcs.awaitExit() shouldBe 0
        }
    }

    // Building an example (with -am) rewrites kernel/target/ktcs-kernel.jar; a kTCS running from it would break.
    test("runs from a copy of the build, so that a build while it runs leaves its jars alone").config(
        enabled = Files.isDirectory(Path.of("/proc/self")),
    ) {
        KtcsProcess(*local).use { ktcs ->
            ktcs.awaitLine("kTCS ready")
            val arguments = Files.readString(Path.of("/proc/${ktcs.pid}/cmdline")).split('\u0000')
            val command = arguments.joinToString(" ")

            command shouldContain "${RepositoryRoot.path}/target/run/"
            command shouldNotContain "kernel/target/ktcs-kernel.jar"
            // kotlin-reflect is the tests' (Kotest, MockK): on kTCS's class path, every typeOf() at start-up would
            // build full reflection descriptors, about a tenth of kTCS's memory.
            jarsOf(arguments[arguments.indexOf("-cp") + 1]).filter { it.startsWith("kotlin-reflect") }.shouldBeEmpty()
            // The copy's manifests are stored (StoredManifests): the JDK keeps no Inflater per open jar for them.
            val compressed = jarPathsOf(arguments[arguments.indexOf("-cp") + 1]).filter { jar ->
                JarFile(jar.toFile()).use { it.getEntry(JarFile.MANIFEST_NAME)?.method == ZipEntry.DEFLATED }
            }
            compressed.shouldBeEmpty()
            ktcs.terminate() shouldBe 0
        }
    }

    // The launcher lowers the compile thresholds of the code an order runs through (README, "Performance"). The JVM
    // prints a command it cannot parse and starts anyway, so only the output shows a broken one.
    test("starts with lower compile thresholds for the order path, and the JVM takes every command silently").config(
        enabled = Files.isDirectory(Path.of("/proc/self")),
    ) {
        KtcsProcess(*local).use { ktcs ->
            ktcs.awaitLine("kTCS ready")
            val arguments = Files.readString(Path.of("/proc/${ktcs.pid}/cmdline")).split('\u0000')

            arguments shouldContainAll listOf(
                "-XX:CompileCommand=quiet",
                "-XX:CompileCommand=CompileThresholdScaling,org.ktcs.*::*,0.3",
                "-XX:CompileCommand=CompileThresholdScaling,io.ktor.*::*,0.3",
                "-XX:CompileCommand=CompileThresholdScaling,org.ktcs.api.model.*::*,1.0",
            )
            ktcs.terminate() shouldBe 0
            ktcs.output() shouldNotContain "CompileCommand"
        }
    }

    test("loads a model given with --model") {
        val model = tempfile("plant", ".xml").toPath()
        Files.writeString(model, TINY_MODEL)
        KtcsProcess("--model", model.toString(), *local).use { ktcs ->
            ktcs.awaitLine("kTCS ready") shouldContain "model 'Tiny' from $model (points=2 paths=1"
            ktcs.terminate() shouldBe 0
        }
    }

    test("a broken model exits non-zero with a one-line error") {
        val model = tempfile("broken", ".xml").toPath()
        Files.writeString(model, TINY_MODEL.replace("destinationPoint=\"B\"", "destinationPoint=\"Nowhere\""))
        KtcsProcess("--model", model.toString(), *local).use { ktcs ->
            ktcs.awaitExit() shouldBe 1
            val output = ktcs.output().lines().filter { it.isNotBlank() }
            output shouldHaveSize 1
            output.single() shouldStartWith "ktcs: error: invalid plant model 'Tiny': path 'A --- B':"
            output.single() shouldContain "Nowhere"
        }
    }

    test("an unknown setting exits non-zero naming the key") {
        KtcsProcess("--set", "web.prot=1").use { ktcs ->
            ktcs.awaitExit() shouldBe 1
            ktcs.output().trim() shouldBe
                "ktcs: error: --set web.prot=1: unknown setting 'web.prot' (did you mean 'web.port'?)"
        }
    }

    test("simulate runs random orders with loopback vehicles on virtual time and prints its figures") {
        KtcsProcess("simulate", "--vehicles", "4", "--orders", "20", "--seed", "3", "--virtual-time").use { ktcs ->
            ktcs.awaitExit(timeout = 120.seconds) shouldBe 0
            val figures = ktcs.output().lines().filter { ": " in it && !it.startsWith("20") }.associate {
                it.substringBefore(": ") to
                    it.substringAfter(": ")
            }
            figures["orders_finished"] shouldBe "20"
            figures["orders_failed"] shouldBe "0"
            figures["double_allocations"] shouldBe "0"
            figures.keys shouldContainAll
                listOf(
                    "makespan_simulated_s",
                    "kernel_cpu_s",
                    "assign_latency_p50_ms",
                    "assign_latency_p99_ms",
                    "assign_wait_p99_ms",
                    "dispatch_run_p99_ms",
                    "route_p50_ms",
                    "route_p99_ms",
                    "deadlocks_detected",
                )
        }
    }

    test("model check prints the summary of a valid model") {
        val model = tempfile("plant", ".xml").toPath()
        Files.writeString(model, TINY_MODEL)
        KtcsProcess("model", "check", model.toString()).use { ktcs ->
            ktcs.awaitExit() shouldBe 0
            ktcs.output().lines().first() shouldBe "points=2 paths=1 locations=1 locationTypes=1 blocks=0 vehicles=1"
        }
    }
})

/** The jar files on [classPath]: its entries, directory wildcards expanded. */
private fun jarPathsOf(classPath: String): List<Path> = classPath.split(':').flatMap { entry ->
    if (entry.endsWith("/*")) {
        Files.list(Path.of(entry.removeSuffix("/*"))).use { jars -> jars.filter { "$it".endsWith(".jar") }.toList() }
    } else {
        listOf(Path.of(entry))
    }
}

/** The names of the jars on [classPath]: its entries, directory wildcards expanded, and what their manifests add. */
private fun jarsOf(classPath: String): List<String> = classPath.split(':').flatMap { entry ->
    if (entry.endsWith("/*")) {
        Files.list(Path.of(entry.removeSuffix("/*"))).use { jars -> jars.map { it.fileName.toString() }.toList() }
    } else {
        val manifestPath = JarFile(entry).use { it.manifest?.mainAttributes?.getValue("Class-Path") }.orEmpty()
        listOf(Path.of(entry).fileName.toString()) +
            manifestPath.split(' ').filter { it.isNotBlank() }.map { Path.of(it).fileName.toString() }
    }
}

private val TINY_MODEL = """
    <?xml version="1.0" encoding="UTF-8" standalone="yes"?>
    <model version="7.0.0" name="Tiny">
        <point name="A" positionX="0" positionY="0" positionZ="0" vehicleOrientationAngle="NaN" type="HALT_POSITION">
            <maxVehicleBoundingBox length="1000" width="1000" height="1000" referenceOffsetX="0" referenceOffsetY="0"/>
            <pointLayout labelOffsetX="-10" labelOffsetY="-20" layerId="0"/>
        </point>
        <point name="B" positionX="5000" positionY="0" positionZ="0" vehicleOrientationAngle="NaN" type="PARK_POSITION">
            <maxVehicleBoundingBox length="1000" width="1000" height="1000" referenceOffsetX="0" referenceOffsetY="0"/>
            <pointLayout labelOffsetX="-10" labelOffsetY="-20" layerId="0"/>
        </point>
        <path name="A --- B" sourcePoint="A" destinationPoint="B" length="5000" maxVelocity="1000" maxReverseVelocity="1000" locked="false">
            <pathLayout connectionType="DIRECT" layerId="0"/>
        </path>
        <vehicle name="V1" energyLevelCritical="30" energyLevelGood="90" energyLevelFullyRecharged="90" energyLevelSufficientlyRecharged="30" maxVelocity="1000" maxReverseVelocity="1000">
            <boundingBox length="1000" width="1000" height="1000" referenceOffsetX="0" referenceOffsetY="0"/>
            <vehicleLayout color="#FF0000"/>
        </vehicle>
        <locationType name="Station">
            <allowedOperation name="Load cargo"/>
            <locationTypeLayout locationRepresentation="LOAD_TRANSFER_GENERIC"/>
        </locationType>
        <location name="Station 1" positionX="5000" positionY="2000" positionZ="0" locked="false" type="Station">
            <link point="B"/>
            <locationLayout labelOffsetX="-10" labelOffsetY="-20" locationRepresentation="DEFAULT" layerId="0"/>
        </location>
        <visualLayout name="VLayout" scaleX="50.0" scaleY="50.0">
            <layer id="0" ordinal="0" visible="true" name="Default layer" groupId="0"/>
            <layerGroup id="0" name="Default layer group" visible="true"/>
        </visualLayout>
    </model>
""".trimIndent()
