package org.ktcs.kernel.persistence

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.persistence.v7.V7_VERSION
import org.ktcs.kernel.persistence.v7.toV7
import java.io.IOException
import java.io.InputStream
import java.nio.file.AccessDeniedException
import java.nio.file.AtomicMoveNotSupportedException
import java.nio.file.FileSystemException
import java.nio.file.Files
import java.nio.file.NoSuchFileException
import java.nio.file.Path
import java.nio.file.StandardCopyOption.ATOMIC_MOVE
import java.nio.file.StandardCopyOption.REPLACE_EXISTING

/**
 * Reads and writes openTCS plant-model XML files.
 *
 * Reading understands schema versions 0.0.2, 0.0.3, 0.0.4, 0.0.5, 6.0.0 and 7.0.0 and converts older versions the
 * way openTCS does; writing always produces 7.0.0 in openTCS's own layout. Reading either returns the whole model or
 * throws [ModelFileException]; it does not check the model's meaning (dangling references, duplicate names, …).
 */
object PlantModelFiles {
    /** The schema version [write] produces. */
    const val WRITTEN_VERSION: String = V7_VERSION

    /** Every schema version [read] accepts, oldest first. */
    val readableVersions: List<String> get() = PlantModelVersions.supported

    /**
     * Reads the plant model in [path].
     *
     * @throws ModelFileException if the file cannot be read, is not well-formed XML, is not a plant model of a
     *   supported version, or holds a value its schema does not allow.
     */
    fun read(path: Path): PlantModel = readWithWarnings(path).model

    /**
     * Reads the plant model in [path] like [read], with warnings for what the reader skipped or changed.
     *
     * @throws ModelFileException as [read] does.
     */
    fun readWithWarnings(path: Path): ModelRead {
        val bytes = try {
            Files.readAllBytes(path)
        } catch (e: IOException) {
            throw ModelFileException("$path: cannot read the file: ${e.describe()}", e)
        }
        return PlantModelVersions.read(bytes, path.toString())
    }

    /**
     * Reads a plant model from [input], naming it [sourceName] in error messages. Does not close [input].
     *
     * @throws ModelFileException as [read] does.
     */
    fun read(input: InputStream, sourceName: String): PlantModel = readWithWarnings(input, sourceName).model

    /**
     * Reads a plant model from [input] like [read], with warnings for what the reader skipped or changed.
     *
     * @throws ModelFileException as [read] does.
     */
    fun readWithWarnings(input: InputStream, sourceName: String): ModelRead {
        val bytes = try {
            input.readAllBytes()
        } catch (e: IOException) {
            throw ModelFileException("$sourceName: cannot read: ${e.describe()}", e)
        }
        return PlantModelVersions.read(bytes, sourceName)
    }

    /**
     * Writes [model] to [path] as a 7.0.0 file, replacing the file only once the new content is complete.
     *
     * @throws ModelFileException if the file cannot be written.
     */
    fun write(model: PlantModel, path: Path) {
        val text = writeToString(model)
        val temporary = path.resolveSibling("${path.fileName}.tmp")
        try {
            Files.writeString(temporary, text)
            replace(temporary, path)
        } catch (e: IOException) {
            runCatching { Files.deleteIfExists(temporary) }
            throw ModelFileException("$path: cannot write the file: ${e.describe()}", e)
        }
    }

    /** The 7.0.0 file content for [model], byte for byte as [write] stores it (UTF-8). */
    fun writeToString(model: PlantModel): String =
        ModelXml.DECLARATION + "\n" + ModelXml.mapper.writeValueAsString(model.toV7())

    private fun replace(source: Path, target: Path) {
        try {
            Files.move(source, target, REPLACE_EXISTING, ATOMIC_MOVE)
        } catch (_: AtomicMoveNotSupportedException) {
            Files.move(source, target, REPLACE_EXISTING)
        }
    }

    /** What went wrong in the user's words: "no such file", not the exception's class name. */
    private fun IOException.describe(): String = when (this) {
        is NoSuchFileException -> "no such file"
        is AccessDeniedException -> "permission denied"
        is FileSystemException -> reason ?: "the file system refused it"
        else -> message ?: "input/output error"
    }
}
