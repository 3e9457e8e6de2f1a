package org.ktcs.kernel.services

import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.OrderSequenceCreation
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.service.TransportOrderService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.store.durably

class StandardTransportOrderService(private val kernel: KernelCore) : TransportOrderService {
    override suspend fun createTransportOrder(creation: TransportOrderCreation): TransportOrder =
        kernel.durably { kernel.createTransportOrder(creation) }

    override suspend fun transportOrder(name: String): TransportOrder? = kernel.context.call { kernel.orders.get(name) }

    override suspend fun transportOrders(intendedVehicle: String?): List<TransportOrder> = kernel.context.call {
        kernel.orders.all().filter { intendedVehicle == null || it.intendedVehicle == intendedVehicle }
    }

    override suspend fun setIntendedVehicle(order: String, vehicle: String?) =
        kernel.durably { kernel.requests.setIntendedVehicle(order, vehicle) }

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
