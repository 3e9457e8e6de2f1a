package org.ktcs.kernel.app

import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardCopyOption
import java.util.zip.CRC32
import java.util.zip.Inflater

/**
 * Rewrites a jar of kTCS's run copy (`target/run/`) so that its manifest is stored uncompressed, every other entry
 * keeping its bytes. The JDK reads the manifest of every jar on the class path when it opens the jar (for its
 * `Class-Path` and `Multi-Release` attributes) and keeps the `Inflater` it used, with zlib's state and 32 KB window,
 * cached with the jar for as long as the jar is open: for the application's class loader, for good. With 130 jars
 * that is about 5 MB of native memory for manifests read once; a stored manifest needs no `Inflater`.
 *
 * The stored manifest goes first as a new entry; the rest of the file follows unchanged (the compressed manifest's
 * bytes stay, unreferenced), and the central directory is written again with its offsets shifted. A jar this does
 * not handle (ZIP64, an unusual manifest, anything that does not check out) is left as it is.
 */
object StoredManifests {
    /** Rewrites [jar] in place; `false` if it was left as it is (manifest stored already, none, or not handled). */
    fun rewrite(jar: Path): Boolean {
        val bytes = Files.readAllBytes(jar)
        val rewritten = rewritten(bytes) ?: return false
        val temporary = Files.createTempFile(jar.parent, ".${jar.fileName}", ".tmp")
        try {
            Files.write(temporary, rewritten)
            Files.move(temporary, jar, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE)
        } finally {
            Files.deleteIfExists(temporary)
        }
        return true
    }

    /** The jar [original] with its manifest stored, or `null` when it is left as it is. */
    fun rewritten(original: ByteArray): ByteArray? {
        val zip = ByteBuffer.wrap(original).order(ByteOrder.LITTLE_ENDIAN)
        val end = endRecord(zip) ?: return null
        val directoryOffset = zip.uint(end + END_DIRECTORY_OFFSET)
        val directorySize = zip.uint(end + END_DIRECTORY_SIZE)
        if (directoryOffset + directorySize != end.toLong()) return null // ZIP64 records or other data in between
        val manifest = manifestRecord(zip, directoryOffset.toInt(), end) ?: return null
        val content = manifestContent(zip, manifest) ?: return null
        val local = storedLocalEntry(zip, manifest, content)
        val shift = local.size
        if (directoryOffset + directorySize + shift > MAX_UINT) return null
        val directory = ByteBuffer.allocate(directorySize.toInt()).order(ByteOrder.LITTLE_ENDIAN)
        directory.put(original, directoryOffset.toInt(), directorySize.toInt())
        var record = 0
        while (record < directorySize) {
            val at = directoryOffset.toInt() + record
            val offset = record + DIR_LOCAL_OFFSET
            if (at == manifest) {
                directory.putShort(record + DIR_FLAGS, (zip.ushort(at + DIR_FLAGS) and DESCRIPTOR_FLAG.inv()).toShort())
                directory.putShort(record + DIR_METHOD, STORED.toShort())
                directory.putInt(record + DIR_COMPRESSED_SIZE, content.size)
                directory.putInt(offset, 0)
            } else {
                directory.putInt(offset, (zip.uint(at + DIR_LOCAL_OFFSET) + shift).toInt())
            }
            record += recordLength(zip, at)
        }
        val endRecord = ByteBuffer.allocate(original.size - end).order(ByteOrder.LITTLE_ENDIAN)
        endRecord.put(original, end, original.size - end)
        endRecord.putInt(END_DIRECTORY_OFFSET, (directoryOffset + shift).toInt())
        val result = ByteArray(shift + original.size)
        System.arraycopy(local, 0, result, 0, shift)
        System.arraycopy(original, 0, result, shift, directoryOffset.toInt())
        System.arraycopy(directory.array(), 0, result, shift + directoryOffset.toInt(), directorySize.toInt())
        System.arraycopy(endRecord.array(), 0, result, shift + end, original.size - end)
        return result
    }

    /** The end-of-central-directory record's position, `null` for a ZIP64 archive or none found. */
    private fun endRecord(zip: ByteBuffer): Int? {
        val lowest = maxOf(0, zip.limit() - END_LENGTH - MAX_COMMENT)
        for (at in zip.limit() - END_LENGTH downTo lowest) {
            if (zip.getInt(at) == END_SIGNATURE && at + END_LENGTH + zip.ushort(at + END_COMMENT) == zip.limit()) {
                val zip64 = at >= ZIP64_LOCATOR_LENGTH && zip.getInt(at - ZIP64_LOCATOR_LENGTH) == ZIP64_LOCATOR
                val multiDisk = zip.ushort(at + END_DISK) != 0 || zip.ushort(at + END_DIRECTORY_DISK) != 0
                return at.takeUnless { zip64 || multiDisk || zip.ushort(at + END_ENTRIES) == MAX_USHORT }
            }
        }
        return null
    }

    /** The central-directory record of a deflated `META-INF/MANIFEST.MF`, `null` if there is none or it is odd. */
    private fun manifestRecord(zip: ByteBuffer, directory: Int, end: Int): Int? {
        var at = directory
        var found: Int? = null
        while (at < end) {
            if (at + DIR_LENGTH > end || zip.getInt(at) != DIR_SIGNATURE) return null
            val nameLength = zip.ushort(at + DIR_NAME_LENGTH)
            val name = String(zip.array(), at + DIR_LENGTH, nameLength, Charsets.UTF_8)
            if (name.equals(MANIFEST, ignoreCase = true)) {
                if (found != null) return null
                found = at
            }
            at += recordLength(zip, at)
        }
        if (at != end || found == null) return null
        val method = zip.ushort(found + DIR_METHOD)
        val sizes = listOf(DIR_COMPRESSED_SIZE, DIR_SIZE, DIR_LOCAL_OFFSET).map { zip.uint(found + it) }
        return found.takeIf { method == DEFLATED && sizes.none { it == MAX_UINT } && sizes[1] <= MAX_MANIFEST }
    }

    /** The manifest's bytes, inflated and checked against its size and CRC; `null` if they do not check out. */
    private fun manifestContent(zip: ByteBuffer, record: Int): ByteArray? {
        val local = zip.uint(record + DIR_LOCAL_OFFSET).toInt()
        if (local + LOCAL_LENGTH > zip.limit() || zip.getInt(local) != LOCAL_SIGNATURE) return null
        val data = local + LOCAL_LENGTH + zip.ushort(local + LOCAL_NAME_LENGTH) + zip.ushort(local + LOCAL_EXTRA_LENGTH)
        val compressed = zip.uint(record + DIR_COMPRESSED_SIZE).toInt()
        if (data + compressed > zip.limit()) return null
        val content = ByteArray(zip.uint(record + DIR_SIZE).toInt())
        val inflater = Inflater(true)
        try {
            inflater.setInput(zip.array(), data, compressed)
            var filled = 0
            while (filled < content.size) {
                val read = inflater.inflate(content, filled, content.size - filled)
                if (read == 0 && (inflater.finished() || inflater.needsInput() || inflater.needsDictionary())) break
                filled += read
            }
            if (filled != content.size) return null
        } finally {
            inflater.end()
        }
        val crc = CRC32().apply { update(content) }.value
        return content.takeIf { crc == zip.uint(record + DIR_CRC) }
    }

    /** A local entry for the manifest [content], stored, with the name, time and CRC of its directory [record]. */
    private fun storedLocalEntry(zip: ByteBuffer, record: Int, content: ByteArray): ByteArray {
        val nameLength = zip.ushort(record + DIR_NAME_LENGTH)
        val entry = ByteBuffer.allocate(LOCAL_LENGTH + nameLength + content.size).order(ByteOrder.LITTLE_ENDIAN)
        entry.putInt(LOCAL_SIGNATURE)
        entry.putShort(STORED_VERSION.toShort())
        entry.putShort((zip.ushort(record + DIR_FLAGS) and DESCRIPTOR_FLAG.inv()).toShort())
        entry.putShort(STORED.toShort())
        entry.putInt(zip.getInt(record + DIR_TIME)) // time and date
        entry.putInt(zip.getInt(record + DIR_CRC))
        entry.putInt(content.size)
        entry.putInt(content.size)
        entry.putShort(nameLength.toShort())
        entry.putShort(0)
        entry.put(zip.array(), record + DIR_LENGTH, nameLength)
        entry.put(content)
        return entry.array()
    }

    private fun recordLength(zip: ByteBuffer, at: Int): Int =
        DIR_LENGTH + zip.ushort(at + DIR_NAME_LENGTH) + zip.ushort(at + DIR_EXTRA_LENGTH) +
            zip.ushort(at + DIR_COMMENT_LENGTH)

    private fun ByteBuffer.ushort(at: Int): Int = getShort(at).toInt() and MAX_USHORT

    private fun ByteBuffer.uint(at: Int): Long = getInt(at).toLong() and MAX_UINT

    private const val MANIFEST = "META-INF/MANIFEST.MF"
    private const val MAX_MANIFEST = 16L shl 20
    private const val STORED = 0
    private const val DEFLATED = 8
    private const val STORED_VERSION = 10
    private const val DESCRIPTOR_FLAG = 0x8
    private const val MAX_USHORT = 0xFFFF
    private const val MAX_UINT = 0xFFFFFFFFL
    private const val MAX_COMMENT = 0xFFFF

    private const val LOCAL_SIGNATURE = 0x04034b50
    private const val LOCAL_LENGTH = 30
    private const val LOCAL_NAME_LENGTH = 26
    private const val LOCAL_EXTRA_LENGTH = 28

    private const val DIR_SIGNATURE = 0x02014b50
    private const val DIR_LENGTH = 46
    private const val DIR_FLAGS = 8
    private const val DIR_METHOD = 10
    private const val DIR_TIME = 12
    private const val DIR_CRC = 16
    private const val DIR_COMPRESSED_SIZE = 20
    private const val DIR_SIZE = 24
    private const val DIR_NAME_LENGTH = 28
    private const val DIR_EXTRA_LENGTH = 30
    private const val DIR_COMMENT_LENGTH = 32
    private const val DIR_LOCAL_OFFSET = 42

    private const val END_SIGNATURE = 0x06054b50
    private const val END_LENGTH = 22
    private const val END_DISK = 4
    private const val END_DIRECTORY_DISK = 6
    private const val END_ENTRIES = 10
    private const val END_DIRECTORY_SIZE = 12
    private const val END_DIRECTORY_OFFSET = 16
    private const val END_COMMENT = 20
    private const val ZIP64_LOCATOR = 0x07064b50
    private const val ZIP64_LOCATOR_LENGTH = 20
}

/** Called by the launcher on the jars of a new run copy: each argument is a jar to rewrite in place. */
fun main(args: Array<String>) {
    args.forEach { jar -> runCatching { StoredManifests.rewrite(Path.of(jar)) } }
}
