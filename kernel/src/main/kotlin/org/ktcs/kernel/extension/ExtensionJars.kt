package org.ktcs.kernel.extension

import org.ktcs.extension.ExtensionException
import java.io.IOException
import java.net.URLClassLoader
import java.nio.file.Files
import java.nio.file.Path
import java.util.jar.JarFile
import kotlin.io.path.extension
import kotlin.io.path.isDirectory
import kotlin.io.path.isRegularFile
import kotlin.io.path.listDirectoryEntries

/**
 * The extension jars of one directory (`extensions.directory`), like openTCS's `lib/openTCS-extensions/`: every
 * `*.jar` there goes into one class loader whose parent is the application's, so extensions see kTCS and each other.
 */
class ExtensionJars private constructor(val jars: List<Path>, val classLoader: ClassLoader) {
    /** The jar [type] was loaded from, or `null` when it comes from the application's class path. */
    fun jarOf(type: Class<*>): Path? {
        val location = type.protectionDomain?.codeSource?.location ?: return null
        val path = runCatching { Path.of(location.toURI()) }.getOrNull() ?: return null
        return jars.firstOrNull { Files.isSameFile(it, path) }
    }

    /** The jars whose `META-INF/services` file for extensions names [className]. */
    fun jarsListing(className: String): List<Path> = jars.filter { jar ->
        JarFile(jar.toFile()).use { file ->
            listOf(Extensions.SERVICE_FILE, Extensions.OLD_SERVICE_FILE).any { name ->
                val entry = file.getJarEntry(name) ?: return@any false
                file.getInputStream(entry).bufferedReader().readLines()
                    .any { it.substringBefore('#').trim() == className }
            }
        }
    }

    companion object {

        /**
         * Opens the jars in [directory]. A missing directory means no extension jars, unless it was [required]
         * (configured explicitly); an unreadable jar is an [ExtensionException] naming it.
         */
        fun open(directory: Path, required: Boolean, parent: ClassLoader): ExtensionJars {
            val absolute = directory.toAbsolutePath().normalize()
            if (!Files.exists(absolute)) {
                if (required) {
                    throw ExtensionException(
                        "extensions directory '$absolute' (extensions.directory) does not exist",
                    )
                }
                return ExtensionJars(emptyList(), parent)
            }
            if (!absolute.isDirectory()) {
                throw ExtensionException("extensions directory '$absolute' (extensions.directory) is not a directory")
            }
            val jars = absolute.listDirectoryEntries()
                .filter { it.isRegularFile() && it.extension.equals("jar", ignoreCase = true) }
                .sorted()
            jars.forEach(::checkReadable)
            if (jars.isEmpty()) return ExtensionJars(jars, parent)
            return ExtensionJars(jars, URLClassLoader(jars.map { it.toUri().toURL() }.toTypedArray(), parent))
        }

        private fun checkReadable(jar: Path) {
            try {
                JarFile(jar.toFile()).use { it.manifest }
            } catch (error: IOException) {
                throw ExtensionException("extension jar '$jar' cannot be read: ${error.describe()}", error)
            }
        }
    }
}
