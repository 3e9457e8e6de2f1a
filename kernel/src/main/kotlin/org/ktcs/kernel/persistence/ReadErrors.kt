package org.ktcs.kernel.persistence

import com.fasterxml.jackson.core.JsonLocation
import com.fasterxml.jackson.core.JsonProcessingException
import com.fasterxml.jackson.core.exc.InputCoercionException
import com.fasterxml.jackson.databind.JsonMappingException
import com.fasterxml.jackson.databind.exc.InvalidFormatException
import com.fasterxml.jackson.databind.exc.MismatchedInputException
import javax.xml.stream.XMLStreamException

// Turns what Woodstox and Jackson throw into one-line messages that point into the file.

internal fun malformed(source: String, e: XMLStreamException): ModelFileException {
    val where = e.location?.let { "$source:${it.lineNumber}:${it.columnNumber}" } ?: source
    return ModelFileException("$where: malformed XML: ${e.detail()}", e)
}

/** Runs [decode] and reports any Jackson failure against [source]. */
internal inline fun <T> decoding(source: String, decode: () -> T): T = try {
    decode()
} catch (e: JsonProcessingException) {
    throw e.toModelFileException(source)
}

internal fun JsonProcessingException.toModelFileException(source: String): ModelFileException {
    causeOfType<XMLStreamException>()?.let { return malformed(source, it) }
    val problem = when (this) {
        is InvalidFormatException -> badValue()

        is MismatchedInputException -> mismatch()

        is JsonMappingException -> causeOfType<InputCoercionException>()?.let { outOfRange(it) }
            ?: "invalid content in ${element()}: ${firstLine(originalMessage)}"

        else -> "malformed XML: ${firstLine(originalMessage)}"
    }
    return ModelFileException("${location.describe(source)}: $problem", this)
}

private inline fun <reified T : Throwable> Throwable.causeOfType(): T? =
    generateSequence(this) { it.cause }.filterIsInstance<T>().firstOrNull()

private fun JsonLocation?.describe(source: String): String =
    if (this == null || lineNr < 0) source else "$source:$lineNr:$columnNr"

private fun InvalidFormatException.badValue(): String =
    "invalid value \"$value\" for attribute \"${attribute()}\" of ${element()} (expected ${expectation(targetType)})"

private fun JsonMappingException.outOfRange(e: InputCoercionException): String =
    "invalid value for attribute \"${attribute()}\" of ${element()} (expected ${expectation(e.targetType)})"

private fun MismatchedInputException.mismatch(): String {
    val missing = originalMessage.contains("missing", ignoreCase = true)
    return if (missing) {
        "${element()} lacks the required attribute or element \"${attribute()}\""
    } else {
        "invalid content for \"${attribute()}\" of ${element()}: ${firstLine(originalMessage)}"
    }
}

private fun JsonMappingException.names(): List<String> = path.mapNotNull { it.fieldName }

private fun JsonMappingException.attribute(): String = names().lastOrNull() ?: "?"

private fun JsonMappingException.element(): String = "<${names().dropLast(1).lastOrNull() ?: "model"}>"

private fun expectation(type: Class<*>?): String = when (type?.kotlin?.javaObjectType) {
    null -> "another value"
    Int::class.javaObjectType -> "a whole number that fits in 32 bits"
    Long::class.javaObjectType -> "a whole number that fits in 64 bits"
    Boolean::class.javaObjectType -> "true or false"
    Double::class.javaObjectType -> "a number, INF, -INF or NaN"
    else -> if (type.isEnum) "one of ${type.enumConstants.joinToString { (it as Enum<*>).name }}" else type.simpleName
}

private fun XMLStreamException.detail(): String = firstLine(message)
    .removePrefix("ParseError at [row,col]:")
    .substringAfter("Message: ")

private fun firstLine(text: String?): String = text.orEmpty().lineSequence().first().trim()
