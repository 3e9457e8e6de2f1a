package org.ktcs.kernel.extension

import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.Setting
import org.slf4j.LoggerFactory
import java.nio.file.Path
import java.util.ServiceConfigurationError
import java.util.ServiceLoader

/** Finds the extensions; a broken one stops the start with a message that names it (and its jar). */
object Extensions {
    /** Where an extension jar lists its [KtcsExtension] classes. */
    val SERVICE_FILE = "META-INF/services/${KtcsExtension::class.java.name}"

    /** The service file's name while the interface lived in the kernel; still read, with a warning. */
    const val OLD_SERVICE_FILE = "META-INF/services/org.ktcs.kernel.extension.KtcsExtension"

    private val log = LoggerFactory.getLogger(Extensions::class.java)

    /** The extensions on the application's class path and in the jars of [directory] (see [ExtensionJars]). */
    fun load(directory: Path, required: Boolean): InstalledExtensions {
        val jars = ExtensionJars.open(directory, required, Extensions::class.java.classLoader)
        return InstalledExtensions(jars.classLoader, discover(jars.classLoader, jars), jars)
    }

    /** The extensions that [classLoader] lists in [SERVICE_FILE] (or [OLD_SERVICE_FILE]). */
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
        val known = found.map { it.javaClass.name }.toSet()
        found += listedUnderOldName(classLoader).filter { it !in known }.map { instantiate(it, classLoader) }
        return found.sortedBy { it.name }
    }

    private fun listedUnderOldName(classLoader: ClassLoader): List<String> =
        classLoader.getResources(OLD_SERVICE_FILE).toList().flatMap { url ->
            log.warn("{} lists kTCS extensions under the old name; rename it to {}", url, SERVICE_FILE)
            url.openStream().bufferedReader().use { it.readLines() }
                .map { it.substringBefore('#').trim() }
                .filter { it.isNotEmpty() }
        }.distinct()

    private fun instantiate(className: String, classLoader: ClassLoader): KtcsExtension {
        val type = try {
            Class.forName(className, false, classLoader)
        } catch (error: ReflectiveOperationException) {
            throw ExtensionException("a kTCS extension could not be loaded: $className: ${error.describe()}", error)
        } catch (error: LinkageError) {
            throw ExtensionException("a kTCS extension could not be loaded: $className: ${error.describe()}", error)
        }
        if (!KtcsExtension::class.java.isAssignableFrom(type)) {
            throw ExtensionException(
                "$className is listed in $OLD_SERVICE_FILE but does not implement ${KtcsExtension::class.java.name}: " +
                    "build it against ktcs-extension-api",
            )
        }
        return try {
            type.getDeclaredConstructor().newInstance() as KtcsExtension
        } catch (error: ReflectiveOperationException) {
            throw ExtensionException("a kTCS extension could not be created: $className: ${error.describe()}", error)
        }
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

    /** The settings every extension declares. */
    val settings: List<Setting<*>> get() = extensions.flatMap { it.settings }
}

/** The message of every cause, joined, so that a one-line report keeps the reason. */
internal fun Throwable.describe(): String = generateSequence(this) { it.cause }
    .joinToString(": caused by ") { it.message ?: it.javaClass.name }
