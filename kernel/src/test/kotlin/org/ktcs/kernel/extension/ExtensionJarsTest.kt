package org.ktcs.kernel.extension

import com.example.extensions.WorkingExtension
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.engine.spec.tempfile
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.collections.shouldNotContain
import io.kotest.matchers.string.shouldContain
import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import java.nio.file.Files
import java.nio.file.Path
import java.util.jar.JarEntry
import java.util.jar.JarOutputStream

/** Extension jars in the extensions directory: found, or a clear error naming the directory, jar or class. */
class ExtensionJarsTest : FunSpec({
    val serviceFile = "META-INF/services/${KtcsExtension::class.java.name}"

    fun jar(directory: Path, name: String, vararg providers: String): Path {
        val jar = directory.resolve(name)
        JarOutputStream(Files.newOutputStream(jar)).use { out ->
            out.putNextEntry(JarEntry(serviceFile))
            out.write(providers.joinToString("\n").toByteArray())
            out.closeEntry()
        }
        return jar
    }

    fun directory(): Path = tempdir("ktcs-extensions").toPath()

    fun names(installed: InstalledExtensions) = installed.extensions.map { it.name }

    test("a missing directory that was not configured means no extension jars") {
        val installed = Extensions.load(directory().resolve("extensions"), required = false)
        names(installed) shouldNotContain "working"
    }

    test("a missing directory that was configured stops the start and is named") {
        val missing = directory().resolve("plugins")
        val error = shouldThrow<ExtensionException> { Extensions.load(missing, required = true) }
        error.message shouldContain "extensions directory '$missing' (extensions.directory) does not exist"
    }

    test("a file given as the directory is refused") {
        val file = tempfile("extensions", ".txt").toPath()
        shouldThrow<ExtensionException> { Extensions.load(file, required = true) }.message shouldContain
            "'$file' (extensions.directory) is not a directory"
    }

    test("the extensions a jar in the directory lists are loaded") {
        val extensions = directory()
        jar(extensions, "working.jar", WorkingExtension::class.java.name)
        names(Extensions.load(extensions, required = true)) shouldContain "working"
    }

    test("files that are not jars are ignored") {
        val extensions = directory()
        Files.writeString(extensions.resolve("README.txt"), "not an extension")
        names(Extensions.load(extensions, required = true)) shouldNotContain "working"
    }

    test("a jar that is not a zip file is named") {
        val extensions = directory()
        val broken = extensions.resolve("broken.jar")
        Files.writeString(broken, "this is not a jar")
        val error = shouldThrow<ExtensionException> { Extensions.load(extensions, required = true) }
        error.message shouldContain "extension jar '$broken' cannot be read"
    }

    test("a listed class that no jar has is named with the jar that lists it") {
        val extensions = directory()
        val listing = jar(extensions, "vendor-driver.jar", "com.example.vendor.VendorDriverExtension")
        val error = shouldThrow<ExtensionException> { Extensions.load(extensions, required = true) }
        error.message shouldContain "com.example.vendor.VendorDriverExtension"
        error.message shouldContain "listed in $listing"
    }

    test("an extension whose constructor fails is named with the reason and its jar") {
        val extensions = directory()
        val listing = jar(extensions, "failing.jar", FailingExtension::class.java.name)
        val error = shouldThrow<ExtensionException> { Extensions.load(extensions, required = true) }
        error.message shouldContain FailingExtension::class.java.name
        error.message shouldContain "no licence key"
        error.message shouldContain "listed in $listing"
    }
})
