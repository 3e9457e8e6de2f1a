package org.ktcs.kernel.web.v1

import org.ktcs.api.error.InvalidRequestException
import java.time.Instant
import java.time.format.DateTimeParseException

/** This value, or an [InvalidRequestException] saying that [field] is missing. */
fun <T : Any> T?.required(field: String): T = this ?: throw InvalidRequestException("$field is missing")

/** The constant of [E] named [value], or an [InvalidRequestException] naming [field] and the allowed values. */
inline fun <reified E : Enum<E>> parseEnum(value: String, field: String): E =
    enumValues<E>().firstOrNull { it.name == value }
        ?: throw InvalidRequestException(
            "$field has unknown value '$value', expected one of ${enumValues<E>().joinToString { it.name }}",
        )

/** [value] read as an ISO-8601 instant, or an [InvalidRequestException] naming [field]. */
fun parseInstant(value: String, field: String): Instant = try {
    Instant.parse(value)
} catch (e: DateTimeParseException) {
    throw InvalidRequestException("$field is not an ISO-8601 timestamp: '$value'")
}

/** Fails with an [InvalidRequestException] naming [field] unless [value] is within 0..100. */
fun requirePercent(value: Int, field: String): Int {
    if (value !in 0..100) throw InvalidRequestException("$field must be within 0..100, was $value")
    return value
}

/** openTCS's wire form of an instant: ISO-8601 in UTC, e.g. `1970-01-01T00:00:00Z`. */
fun Instant.toWire(): String = toString()
