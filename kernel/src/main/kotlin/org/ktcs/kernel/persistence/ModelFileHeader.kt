package org.ktcs.kernel.persistence

import java.io.ByteArrayInputStream
import javax.xml.stream.XMLStreamConstants.DTD
import javax.xml.stream.XMLStreamConstants.START_ELEMENT
import javax.xml.stream.XMLStreamException
import javax.xml.stream.XMLStreamReader

/** What the root element of a plant-model file says about the file, read before choosing a parser. */
internal data class ModelFileHeader(val version: String, val where: String)

/** Reads only up to the root element of [bytes] and checks that it is a `<model>` with a `version`. */
internal fun peekHeader(bytes: ByteArray, source: String): ModelFileHeader {
    val reader = try {
        ModelXml.inputFactory.createXMLStreamReader(ByteArrayInputStream(bytes))
    } catch (e: XMLStreamException) {
        throw malformed(source, e)
    }
    try {
        reader.toRootElement(source)
        return reader.checkedHeader(source)
    } catch (e: XMLStreamException) {
        throw malformed(source, e)
    } finally {
        reader.close()
    }
}

private fun XMLStreamReader.toRootElement(source: String) {
    while (next() != START_ELEMENT) {
        if (eventType == DTD) throw ModelFileException("${where(source)}: a plant model must not have a DOCTYPE")
    }
}

private fun XMLStreamReader.checkedHeader(source: String): ModelFileHeader {
    if (localName != "model" || !namespaceURI.isNullOrEmpty()) {
        throw ModelFileException(
            "${where(source)}: expected root element <model> of a plant model, found <${qualifiedName()}>",
        )
    }
    val version = getAttributeValue(null, "version")
        ?: throw ModelFileException("${where(source)}: <model> has no version attribute (${supportedVersionsText()})")
    return ModelFileHeader(version, where(source))
}

private fun XMLStreamReader.where(source: String) = "$source:${location.lineNumber}:${location.columnNumber}"

private fun XMLStreamReader.qualifiedName(): String = if (prefix.isNullOrEmpty()) localName else "$prefix:$localName"

internal fun supportedVersionsText(): String = "supported versions: ${PlantModelVersions.supported.joinToString()}"
