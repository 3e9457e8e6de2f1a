package org.ktcs.kernel.orders

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.error.ObjectUnknownException
import org.ktcs.api.kernel.KernelClock
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.XmlSafeText
import org.ktcs.api.order.Destination
import org.ktcs.api.order.DriveOrder
import org.ktcs.api.order.Operations
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.workingset.ObjectNames

/**
 * Turns a [TransportOrderCreation] into a RAW [TransportOrder], with openTCS's rules: a unique name (completed if
 * incomplete), at least one destination, a location destination's operation allowed by its type and by at least one
 * of its links (links without operations allow all; NOP is always allowed), a point destination's operation MOVE
 * or PARK, known intended vehicle and dependencies, and a wrapping sequence that accepts the order. Names, type,
 * operations and properties must hold only characters XML can carry ([XmlSafeText]).
 */
class TransportOrderFactory(private val clock: KernelClock, private val names: ObjectNames) {
    fun create(
        creation: TransportOrderCreation,
        model: PlantModel,
        nameTaken: (String) -> Boolean,
        orderExists: (String) -> Boolean,
        sequence: (String) -> OrderSequence?,
    ): TransportOrder {
        checkText(creation)
        val name = if (creation.incompleteName) names.complete(creation.name) else creation.name
        if (name.isBlank()) throw InvalidRequestException("a transport order needs a name")
        if (nameTaken(name)) throw ObjectExistsException("an object named '$name' exists already")
        if (creation.destinations.isEmpty()) {
            throw InvalidRequestException(
                "transport order '$name' has no destinations",
            )
        }
        creation.destinations.forEachIndexed { index, destination -> checkDestination(name, index, destination, model) }
        creation.intendedVehicle?.let {
            if (model.vehicle(it) == null) {
                throw ObjectUnknownException("transport order '$name': unknown intended vehicle '$it'")
            }
        }
        creation.dependencies.forEach {
            if (!orderExists(it)) throw ObjectUnknownException("transport order '$name': unknown dependency '$it'")
        }
        creation.wrappingSequence?.let {
            checkSequence(
                name,
                creation,
                sequence(it) ?: throw ObjectUnknownException("transport order '$name': unknown order sequence '$it'"),
            )
        }
        if (creation.peripheralReservationToken?.isEmpty() == true) {
            throw InvalidRequestException("transport order '$name': the peripheral reservation token must not be empty")
        }
        return TransportOrder(
            name = name,
            driveOrders = creation.destinations.mapIndexed { index, destination ->
                DriveOrder(driveOrderName(index, destination), destination)
            },
            type = creation.type,
            creationTime = clock.now(),
            deadline = creation.deadline,
            intendedVehicle = creation.intendedVehicle,
            dependencies = creation.dependencies,
            wrappingSequence = creation.wrappingSequence,
            dispensable = creation.dispensable,
            peripheralReservationToken = creation.peripheralReservationToken,
            properties = creation.properties,
        )
    }

    private fun checkText(creation: TransportOrderCreation) {
        XmlSafeText.require(creation.name, "the transport order name '${XmlSafeText.printable(creation.name)}'")
        val order = "transport order '${XmlSafeText.printable(creation.name)}'"
        XmlSafeText.require(creation.type, "$order: the type")
        XmlSafeText.requireProperties(creation.properties, order)
        creation.destinations.forEachIndexed { index, destination ->
            val where = "$order, destination ${index + 1}"
            XmlSafeText.require(destination.target, "$where: the location or point name")
            XmlSafeText.require(destination.operation, "$where: the operation")
            XmlSafeText.requireProperties(destination.properties, where)
        }
    }

    private fun driveOrderName(index: Int, destination: Destination) = "${index.toString().padStart(
        2,
        '0',
    )}:${destination.target}:${destination.operation}"

    private fun checkDestination(order: String, index: Int, destination: Destination, model: PlantModel) {
        val where = "transport order '$order', destination ${index + 1}"
        model.point(destination.target)?.let {
            if (destination.operation != Operations.MOVE && destination.operation != Operations.PARK) {
                throw InvalidRequestException(
                    "$where: operation '${destination.operation}' at point '${it.name}' must be MOVE or PARK",
                )
            }
            return
        }
        val location = model.location(destination.target)
            ?: throw ObjectUnknownException("$where: unknown location or point '${destination.target}'")
        if (destination.operation == Operations.NOP) return
        val type =
            model.locationType(location.type)
                ?: throw ObjectUnknownException("$where: unknown location type '${location.type}'")
        if (destination.operation !in type.allowedOperations) {
            throw InvalidRequestException(
                "$where: operation '${destination.operation}' is not allowed at location '${location.name}' " +
                    "(type '${type.name}' allows ${type.allowedOperations.sorted().joinToString().ifEmpty { "none" }})",
            )
        }
        if (location.links.none { it.allowedOperations.isEmpty() || destination.operation in it.allowedOperations }) {
            throw InvalidRequestException(
                "$where: no link of location '${location.name}' allows operation '${destination.operation}'",
            )
        }
    }

    private fun checkSequence(order: String, creation: TransportOrderCreation, sequence: OrderSequence) {
        val where = "transport order '$order'"
        if (sequence.complete) {
            throw IllegalStateChangeException(
                "$where: order sequence '${sequence.name}' is complete",
            )
        }
        if (sequence.finished) {
            throw IllegalStateChangeException(
                "$where: order sequence '${sequence.name}' is finished",
            )
        }
        if ("*" !in sequence.orderTypes && creation.type !in sequence.orderTypes) {
            throw InvalidRequestException(
                "$where: type '${creation.type}' is not one of order sequence '${sequence.name}''s types ${sequence.orderTypes.sorted()}",
            )
        }
        if (sequence.intendedVehicle != creation.intendedVehicle) {
            throw InvalidRequestException(
                "$where: intended vehicle '${creation.intendedVehicle}' differs from order sequence '${sequence.name}''s '${sequence.intendedVehicle}'",
            )
        }
    }
}
