package org.ktcs.kernel.web.ws

import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.orders.waitingReason
import org.ktcs.kernel.web.ws.OrderField.CREATION_TIME
import org.ktcs.kernel.web.ws.OrderField.CURRENT_DRIVE_ORDER_INDEX
import org.ktcs.kernel.web.ws.OrderField.CURRENT_ROUTE_STEP_INDEX
import org.ktcs.kernel.web.ws.OrderField.DEADLINE
import org.ktcs.kernel.web.ws.OrderField.DEPENDENCIES
import org.ktcs.kernel.web.ws.OrderField.DISPENSABLE
import org.ktcs.kernel.web.ws.OrderField.FINISHED_TIME
import org.ktcs.kernel.web.ws.OrderField.HISTORY
import org.ktcs.kernel.web.ws.OrderField.INTENDED_VEHICLE
import org.ktcs.kernel.web.ws.OrderField.NAME
import org.ktcs.kernel.web.ws.OrderField.PERIPHERAL_RESERVATION_TOKEN
import org.ktcs.kernel.web.ws.OrderField.PROCESSING_VEHICLE
import org.ktcs.kernel.web.ws.OrderField.PROPERTIES
import org.ktcs.kernel.web.ws.OrderField.STATE
import org.ktcs.kernel.web.ws.OrderField.TYPE
import org.ktcs.kernel.web.ws.OrderField.WAITING_REASON
import org.ktcs.kernel.web.ws.OrderField.WRAPPING_SEQUENCE

/**
 * A transport order's event state as UTF-8 JSON, written field by field straight from the [TransportOrder]: byte for
 * byte what [org.ktcs.kernel.web.v1.V1Json] writes for [org.ktcs.kernel.web.v1.events.toSseDto], without building
 * the DTOs, encoding them and splicing the routes and the history into the result. Most order events are an order
 * advancing a step, which a client that keeps the latest state gets without its drive orders, history and the other
 * fields that did not change: those are then neither encoded nor copied. The values that seldom change are copied
 * from [steady], the routes from [org.ktcs.kernel.web.v1.events.EncodedRoutes] and the history from [history] (each
 * asked for only when written). Each result is a new array made to its size (the fields are measured first), so one
 * instance serves several threads.
 */
internal class OrderJsonWriter(
    private val order: TransportOrder,
    private val steady: SteadyOrderFields,
    private val history: Lazy<ByteArray>,
) : FieldByFieldJson<OrderField>(OrderField.FIELDS) {
    private val waitingReason = order.waitingReason()

    // Each drive order's route: looked up once, when the drive orders are first written (measured, then copied).
    private val routes: Array<ByteArray> by lazy { steady.driveOrders.parts.map { it.routeJson() }.toTypedArray() }

    override fun isPresent(field: OrderField) = field != WAITING_REASON || waitingReason != null

    override fun writeValue(field: OrderField, out: Utf8JsonOut) = when (field.kind) {
        OrderFieldKind.BYTES -> out.raw(bytesOf(field))
        OrderFieldKind.TEXT -> out.stringOrNull(textOf(field))
        OrderFieldKind.NUMBER -> out.int(numberOf(field))
        OrderFieldKind.DRIVE_ORDERS -> out.driveOrders(steady.driveOrders.parts, routes)
    }

    override fun sizeOfValue(field: OrderField): Int = when (field.kind) {
        OrderFieldKind.BYTES -> bytesOf(field).size
        OrderFieldKind.TEXT -> textOf(field)?.let { Utf8JsonOut.sizeOf(it) } ?: Utf8JsonOut.NULL.size
        OrderFieldKind.NUMBER -> Utf8JsonOut.sizeOf(numberOf(field).toLong())
        OrderFieldKind.DRIVE_ORDERS -> driveOrdersSize(steady.driveOrders.parts, routes)
    }

    private fun bytesOf(field: OrderField): ByteArray = when (field) {
        NAME -> steady.name.bytes
        PROPERTIES -> steady.properties.bytes
        HISTORY -> history.value
        TYPE -> steady.type.bytes
        DEPENDENCIES -> steady.dependencies.bytes
        STATE -> ORDER_STATES[order.state.ordinal]
        CREATION_TIME -> steady.creationTime.bytes
        DEADLINE -> steady.deadline.bytes
        FINISHED_TIME -> steady.finishedTime.bytes
        DISPENSABLE -> Utf8JsonOut.booleanOf(order.dispensable)
        else -> error("$field is no kept value")
    }

    private fun textOf(field: OrderField): String? = when (field) {
        PERIPHERAL_RESERVATION_TOKEN -> order.peripheralReservationToken
        INTENDED_VEHICLE -> order.intendedVehicle
        PROCESSING_VEHICLE -> order.processingVehicle
        WRAPPING_SEQUENCE -> order.wrappingSequence
        WAITING_REASON -> waitingReason
        else -> error("$field is no string")
    }

    private fun numberOf(field: OrderField): Int = when (field) {
        CURRENT_DRIVE_ORDER_INDEX -> order.currentDriveOrderIndex
        CURRENT_ROUTE_STEP_INDEX -> order.currentRouteStepIndex
        else -> error("$field is no number")
    }
}

/** How a field's value is made: kept as bytes, a string or `null`, an int, the drive orders with their routes. */
internal enum class OrderFieldKind { BYTES, TEXT, NUMBER, DRIVE_ORDERS }

/** The top-level fields of [org.ktcs.kernel.web.v1.events.SseTransportOrderDto], in its order. */
internal enum class OrderField(val wireName: String, val kind: OrderFieldKind) {
    NAME("name", OrderFieldKind.BYTES),
    PROPERTIES("properties", OrderFieldKind.BYTES),
    HISTORY("history", OrderFieldKind.BYTES),
    TYPE("type", OrderFieldKind.BYTES),
    DEPENDENCIES("dependencies", OrderFieldKind.BYTES),
    DRIVE_ORDERS("driveOrders", OrderFieldKind.DRIVE_ORDERS),
    PERIPHERAL_RESERVATION_TOKEN("peripheralReservationToken", OrderFieldKind.TEXT),
    CURRENT_DRIVE_ORDER_INDEX("currentDriveOrderIndex", OrderFieldKind.NUMBER),
    CURRENT_ROUTE_STEP_INDEX("currentRouteStepIndex", OrderFieldKind.NUMBER),
    STATE("state", OrderFieldKind.BYTES),
    CREATION_TIME("creationTime", OrderFieldKind.BYTES),
    DEADLINE("deadline", OrderFieldKind.BYTES),
    FINISHED_TIME("finishedTime", OrderFieldKind.BYTES),
    INTENDED_VEHICLE("intendedVehicle", OrderFieldKind.TEXT),
    PROCESSING_VEHICLE("processingVehicle", OrderFieldKind.TEXT),
    WRAPPING_SEQUENCE("wrappingSequence", OrderFieldKind.TEXT),
    DISPENSABLE("dispensable", OrderFieldKind.BYTES),
    WAITING_REASON("waitingReason", OrderFieldKind.TEXT),
    ;

    companion object {
        val FIELDS = JsonFields(entries.toTypedArray(), OrderField::wireName)
    }
}

private val ORDER_STATES = TransportOrderState.entries.map { jsonString(it.name) }
private const val OPEN_BRACKET = '['.code.toByte()
private const val CLOSE_BRACKET = ']'.code.toByte()
private const val COMMA = ','.code.toByte()

/** The drive orders, each put together from its [DriveOrderJson] parts and its route's JSON ([routes]). */
private fun Utf8JsonOut.driveOrders(parts: Array<DriveOrderJson>, routes: Array<ByteArray>) {
    byte(OPEN_BRACKET)
    for (i in parts.indices) {
        if (i > 0) byte(COMMA)
        raw(parts[i].head)
        raw(routes[i])
        raw(parts[i].tail)
    }
    byte(CLOSE_BRACKET)
}

private fun driveOrdersSize(parts: Array<DriveOrderJson>, routes: Array<ByteArray>): Int {
    var size = 2 + maxOf(parts.size - 1, 0)
    for (i in parts.indices) size += parts[i].head.size + routes[i].size + parts[i].tail.size
    return size
}
