package org.ktcs.kernel.services

import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.TransportOrderState
import org.ktcs.api.service.DispatcherService
import org.ktcs.kernel.core.KernelCore

class StandardDispatcherService(private val kernel: KernelCore) : DispatcherService {
    override suspend fun dispatch() = kernel.context.call { kernel.dispatch() }

    override suspend fun withdrawByTransportOrder(order: String, immediate: Boolean, disableVehicle: Boolean) =
        kernel.context.call { kernel.withdraw(order, immediate, disableVehicle) }

    override suspend fun withdrawByVehicle(
        vehicle: String,
        immediate: Boolean,
        disableVehicle: Boolean,
    ) = kernel.context.call {
        val order = kernel.plant.vehicle(vehicle).transportOrder
        if (order != null) {
            kernel.withdraw(order, immediate, disableVehicle)
        } else if (disableVehicle) {
            kernel.controllers.setIntegrationLevel(vehicle, IntegrationLevel.TO_BE_RESPECTED)
        }
    }

    override suspend fun assignNow(order: String) = kernel.context.call {
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
        val refusal = when {
            vehicle.integrationLevel != IntegrationLevel.TO_BE_UTILIZED ->
                "its integration level is ${vehicle.integrationLevel}"

            vehicle.procState != ProcState.IDLE -> "it is ${vehicle.procState}"

            vehicle.state != VehicleState.IDLE && vehicle.state != VehicleState.CHARGING -> "it is ${vehicle.state}"

            vehicle.currentPosition == null -> "its position is unknown"

            vehicle.orderSequence != null -> "it is bound to order sequence '${vehicle.orderSequence}'"

            else -> null
        }
        refusal?.let { throw IllegalStateChangeException("cannot assign '$order' to vehicle '$vehicleName' now: $it") }
        val driveOrders = kernel.router.routeOrder(vehicle, vehicle.currentPosition!!, current)
            ?: throw IllegalStateChangeException("no route for vehicle '$vehicleName' to carry out '$order'")
        kernel.assign(order, vehicleName, driveOrders)
    }

    override suspend fun reroute(vehicle: String, forced: Boolean) = kernel.context.call {
        kernel.plant.vehicle(vehicle)
        kernel.controllers.controller(vehicle).reroute(emptySet(), forced)?.let {
            throw IllegalStateChangeException("cannot reroute vehicle '$vehicle': $it")
        }
        Unit
    }
}
