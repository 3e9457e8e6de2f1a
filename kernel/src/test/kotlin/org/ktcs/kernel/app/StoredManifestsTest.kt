package org.ktcs.kernel.app

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe
import java.io.ByteArrayOutputStream
import java.nio.file.Files
import java.nio.file.Path
import java.util.jar.Attributes
import java.util.jar.JarFile
import java.util.jar.JarInputStream
import java.util.jar.JarOutputStream
import java.util.jar.Manifest
import java.util.zip.ZipEntry
import java.util.zip.ZipOutputStream

class StoredManifestsTest : FunSpec({
    val contents = mapOf(
        "org/example/A.class" to ByteArray(5000) { (it % 7).toByte() },
        "META-INF/services/org.example.Service" to "org.example.A\n".toByteArray(),
        "empty/" to ByteArray(0),
        "data.txt" to "kTCS ".repeat(2000).toByteArray(),
    )

    fun jar(manifest: Manifest?): Path {
        val bytes = ByteArrayOutputStream()
        val stream = manifest?.let { JarOutputStream(bytes, it) } ?: ZipOutputStream(bytes)
        stream.use { zip ->
            contents.forEach { (name, content) ->
                zip.putNextEntry(ZipEntry(name))
                zip.write(content)
                zip.closeEntry()
            }
        }
        return tempfile("stored-manifests", ".jar").toPath().also { Files.write(it, bytes.toByteArray()) }
    }

    fun manifest() = Manifest().apply {
        mainAttributes[Attributes.Name.MANIFEST_VERSION] = "1.0"
        mainAttributes[Attributes.Name.CLASS_PATH] = "lib/a.jar lib/b.jar"
        mainAttributes[Attributes.Name("Multi-Release")] = "true"
    }

    test("the manifest is stored, and the jar reads as before: manifest, entries and their contents") {
        val jar = jar(manifest())
        JarFile(jar.toFile()).use { it.getEntry(JarFile.MANIFEST_NAME).method } shouldBe ZipEntry.DEFLATED

        StoredManifests.rewrite(jar) shouldBe true

        JarFile(jar.toFile()).use { file ->
            file.getEntry(JarFile.MANIFEST_NAME).method shouldBe ZipEntry.STORED
            file.manifest.mainAttributes shouldBe manifest().mainAttributes
            file.isMultiRelease shouldBe true
            contents.forEach { (name, content) ->
                val entry = file.getEntry(name)
                entry shouldNotBe null
                entry.method shouldBe ZipEntry.DEFLATED
                file.getInputStream(entry).readAllBytes() shouldBe content
            }
            file.size() shouldBe contents.size + 1 // and the manifest
        }
        JarInputStream(Files.newInputStream(jar)).use { stream ->
            stream.manifest.mainAttributes shouldBe manifest().mainAttributes
        }
    }

    test("a jar whose manifest is stored already, or that has none, is left as it is") {
        val none = jar(null)
        val before = Files.readAllBytes(none)
        StoredManifests.rewrite(none) shouldBe false
        Files.readAllBytes(none) shouldBe before

        val jar = jar(manifest())
        StoredManifests.rewrite(jar) shouldBe true
        val once = Files.readAllBytes(jar)
        StoredManifests.rewrite(jar) shouldBe false
        Files.readAllBytes(jar) shouldBe once
    }

    test("a file that is not a jar, or a cut one, is left as it is") {
        StoredManifests.rewritten("not a jar".toByteArray()) shouldBe null
        val whole = Files.readAllBytes(jar(manifest()))
        StoredManifests.rewritten(whole.copyOf(whole.size - 10)) shouldBe null
    }
})
