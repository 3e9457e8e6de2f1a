package org.ktcs.kernel.services

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.service.DispatcherService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.dispatching.VehicleAvailability
import org.ktcs.kernel.store.durably

class StandardDispatcherService(private val kernel: KernelCore) : DispatcherService {
    private val availability = VehicleAvailability(kernel.orders::get, kernel.sequences::get)

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

    override suspend fun assignNow(order: String) = kernel.durably {
        val current = kernel.orders.require(order)
        val vehicleName = current.intendedVehicle
            ?: throw IllegalStateChangeException("transport order '$order' has no intended vehicle to assign it to")
        if (current.state != TransportOrderState.DISPATCHABLE) {
            throw IllegalStateChangeException("transport order '$order' is ${current.state}, not DISPATCHABLE")
        }
        if (current.wrappingSequence != null) {
            throw IllegalStateChangeException("transport order '$order' belongs to a sequence")
        }
        val vehicle = kernel.plant.vehicle(vehicleName)
        val work = VehicleAvailability.Work(orderType = current.type, mayReplaceDispensable = false)
        val refusals = availability.reasons(vehicle, work)
        if (refusals.isNotEmpty()) {
            throw IllegalStateChangeException(
                "cannot assign '$order' to vehicle '$vehicleName' now: ${refusals.joinToString(", ")}",
            )
        }
        val driveOrders = kernel.router.routeOrder(vehicle, vehicle.currentPosition!!, current)
            ?: throw IllegalStateChangeException("no route for vehicle '$vehicleName' to carry out '$order'")
        kernel.assign(order, vehicleName, driveOrders)
    }

    override suspend fun reroute(vehicle: String, forced: Boolean) = kernel.durably {
        kernel.plant.vehicle(vehicle)
        kernel.controllers.controller(vehicle).reroute(emptySet(), forced)?.let {
            throw IllegalStateChangeException("cannot reroute vehicle '$vehicle': $it")
        }
        Unit
    }
}
