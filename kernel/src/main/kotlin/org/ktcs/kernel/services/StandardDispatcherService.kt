package org.ktcs.kernel.services

import org.ktcs.api.service.DispatcherService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.store.durably

class StandardDispatcherService(private val kernel: KernelCore) : DispatcherService {
    override suspend fun dispatch() = kernel.context.call { kernel.dispatch() }

    override suspend fun withdrawByTransportOrder(order: String, immediate: Boolean, disableVehicle: Boolean) =
        kernel.durably { kernel.withdraw(order, immediate, disableVehicle) }

    override suspend fun withdrawByVehicle(
        vehicle: String,
        immediate: Boolean,
        disableVehicle: Boolean,
    ) = kernel.durably { kernel.requests.withdrawByVehicle(vehicle, immediate, disableVehicle) }

    override suspend fun assignNow(order: String) = kernel.durably { kernel.requests.assignNow(order) }

    override suspend fun reroute(vehicle: String, forced: Boolean) =
        kernel.durably { kernel.requests.reroute(vehicle, forced) }
}
