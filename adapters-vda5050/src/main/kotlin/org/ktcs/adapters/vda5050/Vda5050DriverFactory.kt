package org.ktcs.adapters.vda5050

import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverPanel
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory

/**
 * Creates [Vda5050Driver]s for the vehicles whose `tcs:preferredAdapterClass` names this driver (or openTCS's VDA 5050
 * driver), and for those with `vda5050:version` and no preferred driver.
 */
class Vda5050DriverFactory(
    private val settings: BrokerSettings = BrokerSettings(),
    private val broker: Vda5050Broker = Vda5050Broker(settings),
) : VehicleDriverFactory {
    override val name: String = NAME

    override val description: String = "VDA 5050 2.0 vehicle over MQTT"

    override val panel: DriverPanel get() = Vda5050Panel.panel

    override fun canDrive(vehicleName: String, context: DriverContext): Boolean {
        val properties = context.vehicle().properties
        val preferred = properties[PREFERRED]
        return preferred == NAME || preferred == OPENTCS_FACTORY || preferred == javaClass.name ||
            Vda5050Properties.VERSION in properties
    }

    override fun claims(vehicleName: String, context: DriverContext): Boolean {
        val properties = context.vehicle().properties
        val preferred = properties[PREFERRED]
        return preferred == OPENTCS_FACTORY || (preferred.isNullOrBlank() && Vda5050Properties.VERSION in properties)
    }

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver {
        val properties = Vda5050Properties.read(vehicleName, context.vehicle().properties)
        return Vda5050Driver(vehicleName, context, properties, broker, settings.mapId)
    }

    companion object {
        /** The factory's name, for `tcs:preferredAdapterClass`. */
        const val NAME: String = "vda5050"

        /** openTCS's VDA 5050 driver, which plants prepared for openTCS name. */
        const val OPENTCS_FACTORY: String = "org.opentcs.commadapter.vehicle.vda5050.CommAdapterFactoryImpl"
        private const val PREFERRED = "tcs:preferredAdapterClass"
    }
}
