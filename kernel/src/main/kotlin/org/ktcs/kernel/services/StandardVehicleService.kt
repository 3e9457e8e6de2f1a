package org.ktcs.kernel.services

import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.DriverPanelView
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.model.AcceptableOrderType
import org.ktcs.api.model.EnergyLevelThresholdSet
import org.ktcs.api.model.IntegrationLevel
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.service.DriverAttachment
import org.ktcs.api.service.VehicleService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.store.durably

class StandardVehicleService(private val kernel: KernelCore) : VehicleService {
    override suspend fun vehicles(procState: ProcState?): List<Vehicle> =
        kernel.context.call { kernel.plant.vehicles().filter { procState == null || it.procState == procState } }

    override suspend fun vehicle(name: String): Vehicle? = kernel.context.call { kernel.plant.vehicleOrNull(name) }

    override suspend fun setIntegrationLevel(vehicle: String, level: IntegrationLevel) =
        kernel.durably { kernel.requests.setIntegrationLevel(vehicle, level) }

    override suspend fun setPaused(vehicle: String, paused: Boolean) = kernel.durably {
        kernel.requests.setPaused(vehicle, paused)
    }

    override suspend fun setAllowedOrderTypes(vehicle: String, types: Set<String>) = update(vehicle) {
        it.copy(allowedOrderTypes = types)
    }

    override suspend fun setAcceptableOrderTypes(vehicle: String, types: Set<AcceptableOrderType>) =
        update(vehicle) { it.copy(acceptableOrderTypes = types) }

    override suspend fun setEnergyLevelThresholdSet(vehicle: String, thresholds: EnergyLevelThresholdSet) =
        kernel.durably { kernel.requests.setEnergyLevelThresholds(vehicle, thresholds) }

    override suspend fun setEnvelopeKey(vehicle: String, key: String?) = update(vehicle) { it.copy(envelopeKey = key) }

    override suspend fun driverAttachment(vehicle: String): DriverAttachment = kernel.context.call {
        kernel.controllers.attachment(vehicle)
    }

    override suspend fun attachDriver(vehicle: String, driver: String) = kernel.durably {
        kernel.requests.attachDriver(vehicle, driver)
    }

    override suspend fun setDriverEnabled(vehicle: String, enabled: Boolean) =
        kernel.durably { kernel.requests.setDriverEnabled(vehicle, enabled) }

    override suspend fun sendDriverMessage(vehicle: String, message: DriverMessage) =
        kernel.context.call { kernel.requests.sendDriverMessage(vehicle, message) }

    override suspend fun driverPanel(vehicle: String): DriverPanelView = kernel.context.call {
        kernel.requests.driverPanel(vehicle)
    }

    override suspend fun executeDriverCommand(
        vehicle: String,
        driver: String,
        command: String,
        parameters: Map<String, String>,
    ) = kernel.context.call { kernel.requests.executeDriverCommand(vehicle, driver, command, parameters) }

    override suspend fun recentDriverEvents(vehicle: String?): List<DriverEvent> = kernel.context.call {
        if (vehicle != null) kernel.plant.vehicle(vehicle)
        kernel.controllers.recentDriverEvents(vehicle)
    }

    private suspend fun update(vehicle: String, change: (Vehicle) -> Vehicle) = kernel.durably {
        kernel.requests.updateVehicle(vehicle, change)
    }
}
