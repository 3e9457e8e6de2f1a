package org.ktcs.kernel.services

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.service.TransportOrderService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.orders.OrderLifecycle
import org.ktcs.kernel.store.durably

class StandardTransportOrderService(private val kernel: KernelCore) : TransportOrderService {
    override suspend fun createTransportOrder(creation: TransportOrderCreation): TransportOrder =
        kernel.durably { kernel.createTransportOrder(creation) }

    override suspend fun transportOrder(name: String): TransportOrder? = kernel.context.call { kernel.orders.get(name) }

    override suspend fun transportOrders(intendedVehicle: String?): List<TransportOrder> = kernel.context.call {
        kernel.orders.all().filter { intendedVehicle == null || it.intendedVehicle == intendedVehicle }
    }

    override suspend fun setIntendedVehicle(order: String, vehicle: String?) = kernel.durably {
        val current = kernel.orders.require(order)
        if (current.state !in OrderLifecycle.UNASSIGNED) {
            throw IllegalStateChangeException(
                "transport order '$order' is ${current.state}; its intended vehicle can only change before it is assigned",
            )
        }
        vehicle?.let { kernel.plant.vehicle(it) }
        kernel.orders.update(order) { it.copy(intendedVehicle = vehicle) }
        kernel.dispatch()
    }

    override suspend fun createOrderSequence(creation: OrderSequenceCreation): OrderSequence =
        kernel.durably { kernel.createOrderSequence(creation) }

    override suspend fun orderSequence(name: String): OrderSequence? = kernel.context.call {
        kernel.sequences.get(name)
    }

    override suspend fun orderSequences(intendedVehicle: String?): List<OrderSequence> = kernel.context.call {
        kernel.sequences.all().filter { intendedVehicle == null || it.intendedVehicle == intendedVehicle }
    }

    override suspend fun markOrderSequenceComplete(name: String) = kernel.durably {
        kernel.markSequenceComplete(name)
    }
}
