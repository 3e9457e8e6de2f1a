package org.ktcs.xmlchannels.orders

import com.fasterxml.jackson.core.JacksonException
import org.ktcs.xmlchannels.HostXml
import java.io.IOException
import java.nio.file.Files
import java.nio.file.NoSuchFileException
import java.nio.file.Path
import javax.xml.stream.XMLStreamException

/** The batch scripts (`.tcs` files) in the scripts directory. */
internal class ScriptFiles(private val directory: Path) {
    /**
     * Reads the script a telegram names. Only the file name's last component counts, as in openTCS, so a telegram
     * can't reach outside the directory.
     */
    fun read(fileName: String): ScriptFileTO {
        val baseName = fileName.substringAfterLast('/').substringAfterLast('\\')
        if (baseName.isBlank() || baseName == "." || baseName == "..") {
            throw TelegramContentException("no script file name in '$fileName'")
        }
        return try {
            parse(Files.readAllBytes(directory.resolve(baseName)), baseName)
        } catch (_: NoSuchFileException) {
            throw TelegramContentException("no script '$baseName' in the scripts directory")
        } catch (error: IOException) {
            throw TelegramContentException("script '$baseName' can't be read: ${error.message}")
        }
    }

    private fun parse(bytes: ByteArray, name: String): ScriptFileTO = try {
        val root = HostXml.wellFormedRootName(bytes)
        if (root != SCRIPT_FILE) throw TelegramContentException("script '$name' is not a $SCRIPT_FILE")
        HostXml.read(bytes)
    } catch (error: XMLStreamException) {
        throw TelegramContentException("script '$name' is not well-formed: ${firstLine(error.message)}")
    } catch (error: JacksonException) {
        throw TelegramContentException(
            "script '$name' is not a valid $SCRIPT_FILE: ${firstLine(error.originalMessage)}",
        )
    }

    private fun firstLine(text: String?) = text.orEmpty().lineSequence().first()

    /** Writes `template.tcs`, an example script, unless it exists. */
    fun writeTemplate() {
        val template = directory.resolve(TEMPLATE)
        if (Files.exists(template)) return
        Files.createDirectories(directory)
        val text = checkNotNull(ScriptFiles::class.java.getResourceAsStream("/org/ktcs/xmlchannels/$TEMPLATE"))
        text.use { Files.copy(it, template) }
    }

    companion object {
        const val TEMPLATE = "template.tcs"
    }
}

/** An order of a telegram or script that can't be carried out; the message is the receipt's reason. */
internal class TelegramContentException(message: String) : Exception(message)
