package org.ktcs.kernel.store

import com.fasterxml.jackson.core.JsonFactory
import com.fasterxml.jackson.core.JsonParser
import com.fasterxml.jackson.core.JsonToken
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.DriveOrderState
import org.ktcs.api.order.HistoryEntry
import org.ktcs.api.order.Route
import org.ktcs.api.order.Step
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import java.time.Instant
import java.util.concurrent.ConcurrentHashMap

/**
 * Reads a stored [TransportOrder] token by token. A restart reads 100,000 of them, and Jackson's Kotlin module spends
 * most of that time in kotlin-reflect finding the constructors' parameters; this reader calls the constructors
 * directly. It reads what [StateCodec] writes (fields in any order, unknown ones skipped, missing ones at the data
 * classes' defaults), so stores written before it are read the same.
 *
 * A reader made to read many orders ([sharingRoutes]) gives equal routes one instance: the routes of 100,000 stored
 * orders are most of their memory and mostly the same few, and every copy kept is one more for the collector to move.
 */
internal class TransportOrderReader private constructor(
    private val factory: JsonFactory,
    private val routes: ConcurrentHashMap<Route, Route>?,
) {
    /** The order [json] holds. */
    fun read(json: String): TransportOrder = factory.createParser(json).use { parser ->
        parser.nextToken()
        order(parser).also { check(parser.nextToken() == null) { "text after the transport order" } }
    }

    private fun order(parser: JsonParser): TransportOrder {
        val defaults = Defaults.order
        var name: String? = null
        var driveOrders: List<DriveOrder>? = null
        var type = defaults.type
        var state = defaults.state
        var creationTime: Instant? = null
        var deadline = defaults.deadline
        var finishedTime: Instant? = null
        var intendedVehicle: String? = null
        var processingVehicle: String? = null
        var dependencies = defaults.dependencies
        var wrappingSequence: String? = null
        var dispensable = defaults.dispensable
        var reservationToken: String? = null
        var driveOrderIndex = defaults.currentDriveOrderIndex
        var stepIndex = defaults.currentRouteStepIndex
        var properties = defaults.properties
        var history = defaults.history
        parser.forEachField { field ->
            when (field) {
                "name" -> name = parser.text()

                "driveOrders" -> driveOrders = parser.list(::driveOrder)

                "type" -> type = StateCodec.shared(parser.required(field))

                "state" -> state = TransportOrderState.valueOf(parser.required(field))

                "creationTime" -> creationTime = parser.instant()

                "deadline" -> deadline = checkNotNull(parser.instant()) { "deadline must not be null" }

                "finishedTime" -> finishedTime = parser.instant()

                "intendedVehicle" -> intendedVehicle = parser.text()?.let(StateCodec::shared)

                "processingVehicle" -> processingVehicle = parser.text()?.let(StateCodec::shared)

                "dependencies" -> dependencies = parser.list {
                    it.required("a dependency")
                }.toCollection(LinkedHashSet())

                "wrappingSequence" -> wrappingSequence = parser.text()

                "dispensable" -> dispensable = parser.booleanValue

                "peripheralReservationToken" -> reservationToken = parser.text()

                "currentDriveOrderIndex" -> driveOrderIndex = parser.intValue

                "currentRouteStepIndex" -> stepIndex = parser.intValue

                "properties" -> properties = parser.properties()

                "history" -> history = parser.list(::historyEntry)

                else -> parser.skipChildren()
            }
        }
        return TransportOrder(
            name = checkNotNull(name) { "a transport order needs a name" },
            driveOrders = checkNotNull(driveOrders) { "transport order $name has no driveOrders" },
            type = type,
            state = state,
            creationTime = checkNotNull(creationTime) { "transport order $name has no creationTime" },
            deadline = deadline,
            finishedTime = finishedTime,
            intendedVehicle = intendedVehicle,
            processingVehicle = processingVehicle,
            dependencies = dependencies,
            wrappingSequence = wrappingSequence,
            dispensable = dispensable,
            peripheralReservationToken = reservationToken,
            currentDriveOrderIndex = driveOrderIndex,
            currentRouteStepIndex = stepIndex,
            properties = properties,
            history = history,
        )
    }

    private fun driveOrder(parser: JsonParser): DriveOrder {
        var name: String? = null
        var destination: Destination? = null
        var route: Route? = null
        var state = DriveOrderState.PRISTINE
        parser.forEachField { field ->
            when (field) {
                "name" -> name = parser.text()
                "destination" -> destination = destination(parser)
                "route" -> route = if (parser.currentToken == JsonToken.VALUE_NULL) null else shared(route(parser))
                "state" -> state = DriveOrderState.valueOf(parser.required(field))
                else -> parser.skipChildren()
            }
        }
        return DriveOrder(
            name = checkNotNull(name) { "a drive order needs a name" },
            destination = checkNotNull(destination) { "drive order $name has no destination" },
            route = route,
            state = state,
        )
    }

    private fun destination(parser: JsonParser): Destination {
        var target: String? = null
        var operation: String? = null
        var properties = emptyMap<String, String>()
        parser.forEachField { field ->
            when (field) {
                "target" -> target = parser.text()?.let(StateCodec::shared)
                "operation" -> operation = parser.text()?.let(StateCodec::shared)
                "properties" -> properties = parser.properties()
                else -> parser.skipChildren()
            }
        }
        return Destination(
            target = checkNotNull(target) { "a destination needs a target" },
            operation = checkNotNull(operation) { "destination $target has no operation" },
            properties = properties,
        )
    }

    private fun route(parser: JsonParser): Route {
        var steps: List<Step>? = null
        var costs: Long? = null
        parser.forEachField { field ->
            when (field) {
                "steps" -> steps = parser.list(StateCodec::step)
                "costs" -> costs = parser.longValue
                else -> parser.skipChildren()
            }
        }
        return Route(
            steps = checkNotNull(steps) { "a route needs steps" },
            costs = checkNotNull(costs) { "a route needs costs" },
        )
    }

    private fun historyEntry(parser: JsonParser): HistoryEntry {
        var timestamp: Instant? = null
        var eventCode: String? = null
        var supplement = ""
        parser.forEachField { field ->
            when (field) {
                "timestamp" -> timestamp = parser.instant()
                "eventCode" -> eventCode = parser.text()?.let(StateCodec::shared)
                "supplement" -> supplement = parser.required(field)
                else -> parser.skipChildren()
            }
        }
        return HistoryEntry(
            timestamp = checkNotNull(timestamp) { "a history entry needs a timestamp" },
            eventCode = checkNotNull(eventCode) { "a history entry needs an eventCode" },
            supplement = supplement,
        )
    }

    private fun shared(route: Route): Route = routes?.run { putIfAbsent(route, route) } ?: route

    /** An order with every default, so the defaults are the data class's and not repeated here. */
    private object Defaults {
        val order = TransportOrder(name = "", driveOrders = emptyList(), creationTime = Instant.EPOCH)
    }

    /** Calls [action] with each field's name, the parser on the field's value; the parser starts on the object. */
    private inline fun JsonParser.forEachField(action: (String) -> Unit) {
        check(currentToken == JsonToken.START_OBJECT) { "expected an object, found $currentToken" }
        while (nextToken() == JsonToken.FIELD_NAME) {
            val field = currentName()
            nextToken()
            action(field)
        }
        check(currentToken == JsonToken.END_OBJECT) { "expected the end of an object, found $currentToken" }
    }

    private fun <T> JsonParser.list(element: (JsonParser) -> T): List<T> {
        check(currentToken == JsonToken.START_ARRAY) { "expected an array, found $currentToken" }
        val elements = ArrayList<T>()
        while (nextToken() != JsonToken.END_ARRAY) elements += element(this)
        return elements
    }

    private fun JsonParser.properties(): Map<String, String> {
        val properties = LinkedHashMap<String, String>()
        forEachField { key -> properties[key] = required(key) }
        return properties
    }

    private fun JsonParser.text(): String? = if (currentToken == JsonToken.VALUE_NULL) null else valueAsString

    private fun JsonParser.required(what: String): String = checkNotNull(text()) { "$what must not be null" }

    private fun JsonParser.instant(): Instant? = text()?.let(StateCodec::instant)

    companion object {
        /** A reader for one order at a time. */
        fun single(factory: JsonFactory) = TransportOrderReader(factory, null)

        /** A reader for all the orders of a store, on any number of threads, sharing equal routes. */
        fun sharingRoutes(factory: JsonFactory) = TransportOrderReader(factory, ConcurrentHashMap())
    }
}
