package org.ktcs.kernel.extension

import java.util.ServiceConfigurationError
import java.util.ServiceLoader

/** Finds the extensions on the class path; a broken one stops the start with a message that names it. */
object Extensions {
    fun discover(classLoader: ClassLoader = Extensions::class.java.classLoader): List<KtcsExtension> {
        val found = mutableListOf<KtcsExtension>()
        val providers = ServiceLoader.load(KtcsExtension::class.java, classLoader).iterator()
        while (true) {
            try {
                if (!providers.hasNext()) break
                found += providers.next()
            } catch (error: ServiceConfigurationError) {
                // ServiceLoader's message names the provider class that is missing or failed.
                throw ExtensionException("a kTCS extension could not be loaded: ${error.describe()}", error)
            }
        }
        return found.sortedBy { it.name }
    }

    private fun Throwable.describe(): String = generateSequence(this) { it.cause }
        .joinToString(": caused by ") { it.message ?: it.javaClass.name }
}

/** An extension that cannot be loaded or started; the message names it. */
class ExtensionException(message: String, cause: Throwable? = null) : RuntimeException(message, cause)
