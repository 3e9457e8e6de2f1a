package org.ktcs.kernel.extension

import java.nio.file.Path
import java.util.ServiceConfigurationError
import java.util.ServiceLoader

/** Finds the extensions; a broken one stops the start with a message that names it (and its jar). */
object Extensions {
    /** The extensions on the application's class path and in the jars of [directory] (see [ExtensionJars]). */
    fun load(directory: Path, required: Boolean): InstalledExtensions {
        val jars = ExtensionJars.open(directory, required, Extensions::class.java.classLoader)
        return InstalledExtensions(jars.classLoader, discover(jars.classLoader, jars), jars)
    }

    /** The extensions that [classLoader] lists in `META-INF/services/org.ktcs.kernel.extension.KtcsExtension`. */
    fun discover(classLoader: ClassLoader = Extensions::class.java.classLoader): List<KtcsExtension> =
        discover(classLoader, null)

    private fun discover(classLoader: ClassLoader, jars: ExtensionJars?): List<KtcsExtension> {
        val found = mutableListOf<KtcsExtension>()
        val providers = ServiceLoader.load(KtcsExtension::class.java, classLoader).iterator()
        while (true) {
            try {
                if (!providers.hasNext()) break
                found += providers.next()
            } catch (error: ServiceConfigurationError) {
                // ServiceLoader's message names the provider class that is missing or failed.
                throw ExtensionException(
                    "a kTCS extension could not be loaded: ${error.describe()}${jars.listing(error)}",
                    error,
                )
            } catch (error: LinkageError) {
                // A provider class that exists but needs a class no jar has (ServiceLoader lets this through).
                throw ExtensionException("a kTCS extension could not be loaded: ${error.describe()}", error)
            }
        }
        return found.sortedBy { it.name }
    }

    private fun ExtensionJars?.listing(error: ServiceConfigurationError): String {
        val provider = PROVIDER.find(error.message.orEmpty())?.groupValues?.get(1) ?: return ""
        val jars = this?.jarsListing(provider).orEmpty()
        return if (jars.isEmpty()) "" else " (listed in ${jars.joinToString()})"
    }

    private val PROVIDER = Regex("""Provider (\S+)""")
}

/** The extensions found at start-up, the class loader that found them and the jars they came from. */
class InstalledExtensions(
    /** Sees the application and every extension jar; the kernel uses it to find drivers too. */
    val classLoader: ClassLoader,
    val extensions: List<KtcsExtension>,
    private val jars: ExtensionJars,
) {
    /** The jar [extension] was loaded from, or `null` when it is part of the application's class path. */
    fun jarOf(extension: KtcsExtension): Path? = jars.jarOf(extension.javaClass)
}

/** An extension that cannot be loaded or started; the message names it. */
class ExtensionException(message: String, cause: Throwable? = null) : RuntimeException(message, cause)

/** The message of every cause, joined, so that a one-line report keeps the reason. */
internal fun Throwable.describe(): String = generateSequence(this) { it.cause }
    .joinToString(": caused by ") { it.message ?: it.javaClass.name }
