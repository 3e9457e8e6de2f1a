package org.ktcs.kernel.store

import com.fasterxml.jackson.core.JsonFactory
import com.fasterxml.jackson.core.JsonGenerator
import com.fasterxml.jackson.core.io.SegmentedStringWriter
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.TransportOrder
import java.time.Instant

/**
 * Writes a [TransportOrder] field by field, the same JSON [StateCodec]'s Jackson mapper writes (fields in alphabetical
 * order, route steps as arrays, instants as `seconds:nanos`; `StateCodecTest` compares the two) and
 * [TransportOrderReader] reads. The store writes an order each time it changes; Jackson's bean serialisers spend most
 * of that time finding and calling accessors.
 */
internal class TransportOrderWriter(private val factory: JsonFactory) {
    /** The JSON of [order]. */
    fun write(order: TransportOrder): String {
        // Jackson's own segmented writer: no synchronised StringBuffer, its buffers recycled between orders.
        val buffers = factory._getBufferRecycler()
        try {
            val text = SegmentedStringWriter(buffers)
            factory.createGenerator(text).use { order(it, order) }
            return text.andClear
        } finally {
            buffers.releaseToPool()
        }
    }

    private fun order(json: JsonGenerator, order: TransportOrder) {
        json.writeStartObject()
        json.instant("creationTime", order.creationTime)
        json.writeNumberField("currentDriveOrderIndex", order.currentDriveOrderIndex)
        json.writeNumberField("currentRouteStepIndex", order.currentRouteStepIndex)
        json.instant("deadline", order.deadline)
        json.writeArrayFieldStart("dependencies")
        order.dependencies.forEach(json::writeString)
        json.writeEndArray()
        json.writeBooleanField("dispensable", order.dispensable)
        json.writeArrayFieldStart("driveOrders")
        order.driveOrders.forEach { driveOrder(json, it) }
        json.writeEndArray()
        json.instant("finishedTime", order.finishedTime)
        json.writeArrayFieldStart("history")
        order.history.forEach { historyEntry(json, it) }
        json.writeEndArray()
        json.writeStringField("intendedVehicle", order.intendedVehicle)
        json.writeStringField("name", order.name)
        json.writeStringField("peripheralReservationToken", order.peripheralReservationToken)
        json.writeStringField("processingVehicle", order.processingVehicle)
        json.properties(order.properties)
        json.writeStringField("state", order.state.name)
        json.writeStringField("type", order.type)
        json.writeStringField("wrappingSequence", order.wrappingSequence)
        json.writeEndObject()
    }

    private fun driveOrder(json: JsonGenerator, driveOrder: DriveOrder) {
        json.writeStartObject()
        json.writeFieldName("destination")
        destination(json, driveOrder.destination)
        json.writeStringField("name", driveOrder.name)
        json.writeFieldName("route")
        driveOrder.route?.let { route(json, it) } ?: json.writeNull()
        json.writeStringField("state", driveOrder.state.name)
        json.writeEndObject()
    }

    private fun destination(json: JsonGenerator, destination: Destination) {
        json.writeStartObject()
        json.writeStringField("operation", destination.operation)
        json.properties(destination.properties)
        json.writeStringField("target", destination.target)
        json.writeEndObject()
    }

    private fun route(json: JsonGenerator, route: Route) {
        json.writeStartObject()
        json.writeNumberField("costs", route.costs)
        json.writeArrayFieldStart("steps")
        route.steps.forEach { StateCodec.step(json, it) }
        json.writeEndArray()
        json.writeEndObject()
    }

    private fun historyEntry(json: JsonGenerator, entry: HistoryEntry) {
        json.writeStartObject()
        json.writeStringField("eventCode", entry.eventCode)
        json.writeStringField("supplement", entry.supplement)
        json.instant("timestamp", entry.timestamp)
        json.writeEndObject()
    }

    private fun JsonGenerator.instant(field: String, instant: Instant?) =
        writeStringField(field, instant?.let(StateCodec::instant))

    private fun JsonGenerator.properties(properties: Map<String, String>) {
        writeObjectFieldStart("properties")
        properties.forEach(::writeStringField)
        writeEndObject()
    }
}
