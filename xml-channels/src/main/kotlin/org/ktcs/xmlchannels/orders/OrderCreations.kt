package org.ktcs.xmlchannels.orders

import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.xmlchannels.toMap
import java.time.DateTimeException
import java.time.Instant
import java.time.LocalDateTime
import java.time.OffsetDateTime
import java.time.ZoneId

/** Created orders get openTCS's name prefix; the kernel appends a unique suffix. */
internal const val ORDER_NAME_PREFIX = "TOrder-"

internal fun OrderTO.toCreation() = TransportOrderCreation(
    name = ORDER_NAME_PREFIX,
    incompleteName = true,
    destinations = destination.map { it.toDestination() },
    deadline = deadline?.let(::parseDeadline) ?: Instant.MAX,
    intendedVehicle = intendedVehicle,
    dependencies = dependency.map(String::trim).toSet(),
    properties = property.toMap(),
)

internal fun ScriptOrderTO.toCreation(dependencies: List<String>) = TransportOrderCreation(
    name = ORDER_NAME_PREFIX,
    incompleteName = true,
    destinations = destination.map { it.toDestination() },
    intendedVehicle = intendedVehicle,
    dependencies = dependencies.toSet(),
)

private fun DestinationTO.toDestination() = Destination(locationName, operation, property.toMap())

/** An `xsd:dateTime`; one without a time zone is local time, as JAXB read it. */
private fun parseDeadline(text: String): Instant = try {
    OffsetDateTime.parse(text.trim()).toInstant()
} catch (_: DateTimeException) {
    try {
        LocalDateTime.parse(text.trim()).atZone(ZoneId.systemDefault()).toInstant()
    } catch (_: DateTimeException) {
        throw TelegramContentException("deadline '$text' is not an xsd:dateTime")
    }
}
