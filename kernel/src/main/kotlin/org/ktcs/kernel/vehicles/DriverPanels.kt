package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.DriverMessage
import org.ktcs.api.driver.DriverPanelView
import org.ktcs.api.error.IllegalStateChangeException
import org.ktcs.api.model.PlantModel

/**
 * What a vehicle's driver panel shows and the commands it sends, checked against the panel of the driver that
 * drives the vehicle before the driver sees them. Confined to the kernel context.
 */
class DriverPanels(private val controllers: VehicleControllers, private val plant: () -> PlantModel) {
    fun view(vehicle: String): DriverPanelView {
        val controller = controllers.controller(vehicle)
        val driver = controller.driver ?: throw noDriver(vehicle)
        val name = controller.driverName ?: throw noDriver(vehicle)
        return DriverPanelView(
            vehicle = vehicle,
            driver = name,
            driverEnabled = driver.isEnabled,
            panel = controllers.factory(name)?.panel,
            state = driver.panelState(),
            commandQueue = controller.commandQueue(),
        )
    }

    fun execute(vehicle: String, driverName: String, command: String, parameters: Map<String, String>) {
        val controller = controllers.controller(vehicle)
        val driver = controller.driver ?: throw noDriver(vehicle)
        if (controller.driverName != driverName) {
            throw IllegalStateChangeException(
                "vehicle '$vehicle' is driven by '${controller.driverName}', not by '$driverName'",
            )
        }
        val panel = controllers.factory(driverName)?.panel
            ?: throw IllegalStateChangeException("driver '$driverName' of vehicle '$vehicle' takes no commands")
        val checked = DriverCommandCheck.check(panel, driverName, command, parameters, plant())
        driver.processMessage(DriverMessage(command, checked))
    }

    private fun noDriver(vehicle: String) = IllegalStateChangeException("vehicle '$vehicle' has no driver attached")
}
