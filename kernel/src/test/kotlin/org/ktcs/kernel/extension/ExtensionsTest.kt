package org.ktcs.kernel.extension

import com.example.extensions.WorkingExtension
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import java.net.URLClassLoader
import java.nio.file.Files

class ExtensionsTest : FunSpec({
    fun classLoaderListing(vararg providers: String, serviceFile: String = Extensions.SERVICE_FILE): ClassLoader {
        val root = tempdir("ktcs-extension").toPath()
        val services = root.resolve(serviceFile)
        Files.createDirectories(services.parent)
        Files.write(services, providers.toList())
        return URLClassLoader(arrayOf(root.toUri().toURL()), ExtensionsTest::class.java.classLoader)
    }

    test("the interface's own name is the service file's name") {
        Extensions.SERVICE_FILE shouldBe "META-INF/services/org.ktcs.extension.KtcsExtension"
        val loader = classLoaderListing(WorkingExtension::class.java.name)
        Extensions.discover(loader).map { it.name } shouldBe listOf("working")
    }

    test("an extension listed under the service file's old name is still found, once") {
        val old = classLoaderListing(
            "# moved from the kernel",
            WorkingExtension::class.java.name,
            serviceFile = Extensions.OLD_SERVICE_FILE,
        )
        Extensions.discover(old).map { it.name } shouldBe listOf("working")
        val both = URLClassLoader(
            emptyArray(),
            classLoaderListing(WorkingExtension::class.java.name, serviceFile = Extensions.OLD_SERVICE_FILE),
        )
        val listedTwice = URLClassLoader(
            (classLoaderListing(WorkingExtension::class.java.name) as URLClassLoader).urLs,
            both,
        )
        Extensions.discover(listedTwice).map { it.name } shouldBe listOf("working")
    }

    test("a class under the old name that is no extension is named with what to do") {
        val error = shouldThrow<ExtensionException> {
            Extensions.discover(classLoaderListing("java.lang.String", serviceFile = Extensions.OLD_SERVICE_FILE))
        }
        error.message shouldContain "java.lang.String"
        error.message shouldContain "build it against ktcs-extension-api"
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
