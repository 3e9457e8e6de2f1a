package org.ktcs.xmlchannels.status

import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import org.ktcs.xmlchannels.HostXml
import org.ktcs.xmlchannels.toPropertyTOs
import java.time.Clock
import java.time.OffsetDateTime
import java.time.format.DateTimeFormatter
import java.time.temporal.ChronoUnit

/**
 * Turns kernel events into status documents. A change shows up only if it changes what the message says: a
 * vehicle's energy level or allocations do not, its position, state or order do.
 */
internal class StatusMessages(private val clock: Clock, private val separator: String) {
    /** The document for [event] with the separator, or `null` if the event says nothing a host sees. */
    fun render(event: KernelEvent): String? {
        val message = messageFor(event) ?: return null
        return withoutSeparator(HostXml.write(StatusMessageSetTO(timeStamp(), listOf(message)))) + separator
    }

    private fun timeStamp() =
        DateTimeFormatter.ISO_OFFSET_DATE_TIME.format(OffsetDateTime.now(clock).truncatedTo(ChronoUnit.MILLIS))

    /**
     * Hosts split the stream at the separator, so it must not occur inside a message, e.g. in a property value. It
     * can only occur in text and attribute values, where a character reference means the same to an XML parser.
     */
    private fun withoutSeparator(document: String): String {
        val first = separator.first()
        if (separator !in document || first.isLetterOrDigit() || first in XML_MARKUP) return document
        return document.replace(separator, "&#${first.code};" + separator.drop(1))
    }

    private fun messageFor(event: KernelEvent): StatusMessageTO? = when (event) {
        is TransportOrderEvent -> changed(event.previous?.toMessage(), event.current?.toMessage())
        is VehicleEvent -> changed(event.previous?.toMessage(), event.current?.toMessage())
        else -> null
    }

    /** Removals are not reported, as a removed order or vehicle has nothing new to say. */
    private fun changed(previous: StatusMessageTO?, current: StatusMessageTO?) = current?.takeIf { it != previous }
}

/** Characters that also occur in markup, where a character reference would change the document. */
private const val XML_MARKUP = "<>&\"'=/?:!-_. \t\r\n"

internal fun TransportOrder.toMessage() = OrderStatusMessageTO(
    orderName = name,
    orderState = state.name,
    processingVehicleName = processingVehicle,
    destination = driveOrders.map { drive ->
        DestinationStatusTO(
            drive.destination.target,
            drive.destination.operation,
            drive.state.name,
            drive.destination.properties.toPropertyTOs(),
        )
    },
    property = properties.toPropertyTOs(),
)

internal fun Vehicle.toMessage() = VehicleStatusMessageTO(
    vehicleName = name,
    transportOrderName = transportOrder,
    position = currentPosition,
    state = state.name,
    processingState = procState.name,
    precisePosition = precisePosition?.let { PrecisePositionTO(it.x, it.y, it.z) },
)
