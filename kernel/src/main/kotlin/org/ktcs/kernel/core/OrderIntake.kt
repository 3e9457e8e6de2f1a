package org.ktcs.kernel.core

import org.ktcs.api.error.ObjectExistsException
import org.ktcs.api.model.XmlSafeText
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.kernel.orders.TransportOrderFactory

/** How new transport orders and order sequences enter the kernel, with their checks. Kernel context. */
internal class OrderIntake(private val state: KernelState) {
    private val factory = TransportOrderFactory(state.context, state.names)

    /** Whether an order, a sequence or a plant object is named [name] already. */
    fun nameTaken(name: String): Boolean = state.orders.contains(name) ||
        state.sequences.get(name) != null ||
        state.plant.staticModel().objectNamed(name) != null

    fun createTransportOrder(creation: TransportOrderCreation): TransportOrder {
        val order = factory.create(
            creation,
            state.plant.layoutWithLocks(),
            ::nameTaken,
            state.orders::contains,
            state.sequences::get,
        )
        state.orders.add(order)
        return state.orders.require(order.name)
    }

    fun createOrderSequence(creation: OrderSequenceCreation): OrderSequence {
        XmlSafeText.require(creation.name, "the order sequence name '${XmlSafeText.printable(creation.name)}'")
        XmlSafeText.require(creation.type, "order sequence '${XmlSafeText.printable(creation.name)}': the type")
        XmlSafeText.requireProperties(creation.properties, "order sequence '${XmlSafeText.printable(creation.name)}'")
        val name = if (creation.incompleteName) state.names.complete(creation.name) else creation.name
        if (nameTaken(name)) throw ObjectExistsException("an object named '$name' exists already")
        creation.intendedVehicle?.let { state.plant.vehicle(it) }
        return state.sequences.add(
            OrderSequence(
                name = name,
                creationTime = state.context.now(),
                type = creation.type,
                orderTypes = creation.orderTypes,
                intendedVehicle = creation.intendedVehicle,
                failureFatal = creation.failureFatal,
                properties = creation.properties,
            ),
        )
    }
}
