package org.ktcs.e2e.extensions

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import org.ktcs.e2e.KtcsProcess
import org.ktcs.extension.KtcsExtension
import java.nio.file.Files
import java.nio.file.Path
import java.util.jar.JarEntry
import java.util.jar.JarOutputStream
import kotlin.io.path.name

/** `./ktcs` with broken jars in its extensions directory: it names the extension and jar, and does not start. */
class ExtensionDirectoryTest : FunSpec({
    val local = listOf("web.bindAddress=127.0.0.1", "web.port=0", "xml.orders.port=0", "xml.status.port=0")

    fun ktcs(extensions: Path) = KtcsProcess(
        *(local + "extensions.directory=$extensions").flatMap { listOf("--set", it) }.toTypedArray(),
    )

    test("an extension whose definition fails at start is named with its jar, exit 1, nothing served") {
        val extensions = tempdir("ktcs-extensions").toPath()
        val jar = extensions.resolve("broken-dispatcher.jar")
        writeJar(jar, BrokenDispatcherExtension::class.java)
        ktcs(extensions).use { ktcs ->
            ktcs.awaitExit() shouldBe 1
            val output = ktcs.output()
            output shouldContain "ktcs: error: extension 'broken-dispatcher' (from $jar) failed to start: "
            output shouldContain "the dispatcher licence has expired"
            output shouldNotContain "kTCS ready"
        }
    }

    test("an extension jar declares settings of its own, set like kTCS's; an undeclared key is still refused") {
        val extensions = tempdir("ktcs-extensions").toPath()
        writeJar(extensions.resolve("greeting.jar"), GreetingExtension::class.java)
        KtcsProcess(
            *(local + "extensions.directory=$extensions" + "greeting.text=moin").flatMap { listOf("--set", it) }
                .toTypedArray(),
        ).use { ktcs ->
            ktcs.awaitLine("kTCS ready") shouldContain "; greeting moin; "
        }
        KtcsProcess(
            *(local + "extensions.directory=$extensions" + "greeting.txt=moin").flatMap { listOf("--set", it) }
                .toTypedArray(),
        ).use { ktcs ->
            ktcs.awaitExit() shouldBe 1
            ktcs.output() shouldContain "unknown setting 'greeting.txt' (did you mean 'greeting.text'?)"
        }
    }

    test("a jar listing a class it does not contain is named, exit 1") {
        val extensions = tempdir("ktcs-extensions").toPath()
        val jar = extensions.resolve("vendor.jar")
        writeJar(jar, providerName = "com.example.vendor.VendorExtension")
        ktcs(extensions).use { ktcs ->
            ktcs.awaitExit() shouldBe 1
            ktcs.output() shouldContain "Provider com.example.vendor.VendorExtension not found (listed in $jar)"
        }
    }
})

/** A jar with [type]'s class files (if any) and a services file listing [providerName]. */
private fun writeJar(jar: Path, type: Class<*>? = null, providerName: String = type!!.name) {
    JarOutputStream(Files.newOutputStream(jar)).use { out ->
        out.putNextEntry(JarEntry("META-INF/services/${KtcsExtension::class.java.name}"))
        out.write(providerName.toByteArray())
        out.closeEntry()
        type?.let { classFilesOf(it) }.orEmpty().forEach { (entry, file) ->
            out.putNextEntry(JarEntry(entry))
            Files.copy(file, out)
            out.closeEntry()
        }
    }
}

/** The class files of [type] and its nested and synthetic classes, by jar entry name. */
private fun classFilesOf(type: Class<*>): List<Pair<String, Path>> {
    val file = Path.of(type.getResource("${type.simpleName}.class")!!.toURI())
    val packagePath = type.packageName.replace('.', '/')
    return Files.list(file.parent).use { files ->
        files.filter { it.name == file.name || it.name.startsWith("${type.simpleName}$") }
            .map { "$packagePath/${it.name}" to it }.toList()
    }
}
