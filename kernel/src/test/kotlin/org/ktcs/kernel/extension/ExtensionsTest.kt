package org.ktcs.kernel.extension

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.string.shouldContain
import java.net.URLClassLoader
import java.nio.file.Files

class ExtensionsTest : FunSpec({
    fun classLoaderListing(vararg providers: String): ClassLoader {
        val root = Files.createTempDirectory("ktcs-extension")
        val services = root.resolve("META-INF/services/${KtcsExtension::class.java.name}")
        Files.createDirectories(services.parent)
        Files.write(services, providers.toList())
        return URLClassLoader(arrayOf(root.toUri().toURL()), ExtensionsTest::class.java.classLoader)
    }

    test("finds nothing when no jar lists an extension") {
        Extensions.discover(classLoaderListing()).shouldBeEmpty()
    }

    test("a listed class that does not exist stops the start and is named") {
        val error =
            shouldThrow<ExtensionException> { Extensions.discover(classLoaderListing("com.example.MissingDriver")) }
        error.message shouldContain "com.example.MissingDriver"
    }

    test("an extension whose constructor fails is named with the reason") {
        val error = shouldThrow<ExtensionException> {
            Extensions.discover(classLoaderListing(FailingExtension::class.java.name))
        }
        error.message shouldContain FailingExtension::class.java.name
        error.message shouldContain "no licence key"
    }
})

class FailingExtension : KtcsExtension {
    init {
        error("no licence key")
    }

    override val name: String = "failing"

    override fun module() = error("unreachable")
}
