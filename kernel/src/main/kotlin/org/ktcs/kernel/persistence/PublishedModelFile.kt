package org.ktcs.kernel.persistence

import org.ktcs.api.model.PlantModel
import java.io.IOException
import java.nio.ByteBuffer
import java.nio.channels.FileChannel
import java.nio.file.AtomicMoveNotSupportedException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardCopyOption.ATOMIC_MOVE
import java.nio.file.StandardCopyOption.REPLACE_EXISTING
import java.nio.file.StandardOpenOption.CREATE_NEW
import java.nio.file.StandardOpenOption.READ
import java.nio.file.StandardOpenOption.WRITE
import java.util.UUID

/**
 * The plant model kTCS publishes to and starts from: `plant-model.xml` in the data directory (setting
 * `kernel.dataDirectory`), an openTCS 7.0.0 file. Each [save] replaces it atomically and keeps the version it
 * replaces as `plant-model.xml.bak`, so a crash at any moment leaves a complete file (the new or the old one).
 */
class PublishedModelFile(val directory: Path) {
    /** The published model's file. */
    val file: Path = directory.resolve(FILE_NAME)

    /** The version [file] had before the last [save]. */
    val backup: Path = directory.resolve("$FILE_NAME.bak")

    /** Whether a model was published here. */
    fun exists(): Boolean = Files.isRegularFile(file)

    /**
     * Writes [model] to a temporary file in the same directory, forces it to the disk, keeps the current file as
     * [backup] and renames the temporary file over [file].
     *
     * @throws ModelFileException if any step fails; [file] is then unchanged.
     */
    fun save(model: PlantModel) {
        val content = PlantModelFiles.writeToString(model).toByteArray(Charsets.UTF_8)
        var temporary: Path? = null
        try {
            Files.createDirectories(directory)
            temporary = temporaryFile(FILE_NAME).also { writeDurably(it, content) }
            if (exists()) keepBackup()
            moveAtomically(temporary, file)
            syncDirectory()
        } catch (error: IOException) {
            throw ModelFileException(
                "$file: cannot publish the plant model: ${error.message ?: error.javaClass.simpleName}",
                error,
            )
        } finally {
            temporary?.let { runCatching { Files.deleteIfExists(it) } }
        }
    }

    /** A copy that is complete before it takes the backup's name: the backup is never half-written either. */
    private fun keepBackup() {
        val copy = temporaryFile("$FILE_NAME.bak")
        try {
            writeDurably(copy, Files.readAllBytes(file))
            moveAtomically(copy, backup)
        } finally {
            Files.deleteIfExists(copy)
        }
    }

    // Not Files.createTempFile: its files are private to the user (0600), and the published model should be as
    // readable as any file kTCS writes (the umask decides).
    private fun temporaryFile(prefix: String): Path = directory.resolve("$prefix.${UUID.randomUUID()}.tmp")

    private fun writeDurably(path: Path, content: ByteArray) {
        FileChannel.open(path, CREATE_NEW, WRITE).use { channel ->
            val buffer = ByteBuffer.wrap(content)
            while (buffer.hasRemaining()) channel.write(buffer)
            channel.force(true)
        }
    }

    private fun moveAtomically(source: Path, target: Path) {
        try {
            Files.move(source, target, REPLACE_EXISTING, ATOMIC_MOVE)
        } catch (_: AtomicMoveNotSupportedException) {
            Files.move(source, target, REPLACE_EXISTING)
        }
    }

    // The rename is durable only once the directory's entry is; some platforms cannot open a directory (ignored).
    private fun syncDirectory() {
        runCatching { FileChannel.open(directory, READ).use { it.force(true) } }
    }

    companion object {
        const val FILE_NAME: String = "plant-model.xml"
    }
}
