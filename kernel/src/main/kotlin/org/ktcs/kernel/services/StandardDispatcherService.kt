package org.ktcs.kernel.services

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.model.IntegrationLevel
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
    ) = kernel.durably {
        val order = kernel.plant.vehicle(vehicle).transportOrder
        if (order != null) {
            kernel.withdraw(order, immediate, disableVehicle)
        } else if (disableVehicle) {
            kernel.controllers.setIntegrationLevel(vehicle, IntegrationLevel.TO_BE_RESPECTED)
        }
    }

    override suspend fun assignNow(order: String) = kernel.durably { kernel.requests.assignNow(order) }

    override suspend fun reroute(vehicle: String, forced: Boolean) = kernel.durably {
        kernel.plant.vehicle(vehicle)
        kernel.controllers.controller(vehicle).reroute(emptySet(), forced)?.let {
            throw IllegalStateChangeException("cannot reroute vehicle '$vehicle': $it")
        }
        Unit
    }
}
