package org.ktcs.kernel.extension

import org.ktcs.extension.ExtensionException
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.ConfigException
import java.net.BindException
import java.nio.file.Path

/**
 * Tells which extension made the start fail: Koin reports a failing definition without saying whose module it
 * was, but the stack trace runs through the extension's own classes.
 */
class ExtensionFailures(private val extensions: List<KtcsExtension>, private val jarOf: (KtcsExtension) -> Path?) {
    /** [error] as an [ExtensionException] naming the extension it came from, or unchanged if none did. */
    fun explain(error: Throwable): Throwable {
        if (error is ExtensionException) return error
        // A port in use or a bad setting is the user's to fix, and the launcher says so in its own words, without
        // the Koin definitions it was found in.
        if (generateSequence(error) { it.cause }.any { it is BindException || it is ConfigException }) return error
        val culprit = culprit(error) ?: return error
        return ExtensionException(
            "extension '${culprit.name}'${jarOf(culprit).from()} failed to start: ${error.describe()}",
            error,
        )
    }

    private fun culprit(error: Throwable): KtcsExtension? {
        val frames = generateSequence(error) { it.cause }.flatMap { it.stackTrace.asSequence() }
        return frames.firstNotNullOfOrNull { frame -> extensions.firstOrNull { it.owns(frame.className) } }
    }

    private fun KtcsExtension.owns(className: String): Boolean {
        val extensionPackage = javaClass.packageName
        return extensionPackage.isNotEmpty() && !extensionPackage.startsWith(KERNEL_PACKAGE) &&
            className.startsWith("$extensionPackage.")
    }

    private companion object {
        const val KERNEL_PACKAGE = "org.ktcs.kernel"
    }
}

/** " (from extensions/x.jar)" for an extension from a jar, "" for one on the class path. */
fun Path?.from(): String = if (this == null) "" else " (from $this)"
