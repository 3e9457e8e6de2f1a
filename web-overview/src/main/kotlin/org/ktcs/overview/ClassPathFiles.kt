package org.ktcs.overview

import io.ktor.http.ContentType
import io.ktor.http.withCharset

/** One file of a front-end directory on the class path. */
class ServedFile(val bytes: ByteArray, val contentType: ContentType)

/**
 * The front-end files below [directory] as [classLoader] sees them. Only plain relative paths to files of the
 * known types are served: no `..`, no absolute paths, no directories.
 */
class ClassPathFiles(private val classLoader: ClassLoader, directory: String) {
    private val directory = directory.trim('/')

    fun read(path: String): ServedFile? {
        val segments = path.split('/')
        if (segments.any { it.isEmpty() || it == "." || it == ".." || '\\' in it }) return null
        val type = contentTypeOf(segments.last()) ?: return null
        val bytes = classLoader.getResourceAsStream("$directory/$path")?.use { it.readBytes() } ?: return null
        return ServedFile(bytes, type)
    }

    private fun contentTypeOf(fileName: String): ContentType? = when (fileName.substringAfterLast('.', "")) {
        "js", "mjs" -> ContentType.Text.JavaScript.withCharset(Charsets.UTF_8)
        "css" -> ContentType.Text.CSS.withCharset(Charsets.UTF_8)
        "html" -> ContentType.Text.Html.withCharset(Charsets.UTF_8)
        "json" -> ContentType.Application.Json
        "svg" -> ContentType.Image.SVG
        "png" -> ContentType.Image.PNG
        "woff2" -> ContentType("font", "woff2")
        else -> null
    }
}
