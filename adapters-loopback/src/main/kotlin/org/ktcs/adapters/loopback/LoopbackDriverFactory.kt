package org.ktcs.adapters.loopback

import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.DriverPanel
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory

/** Creates [LoopbackDriver]s, which can drive any vehicle of the model. */
class LoopbackDriverFactory(private val settings: LoopbackSettings = LoopbackSettings()) : VehicleDriverFactory {
    private val placement = Placement()

    override val name: String = NAME

    override val description: String = "Simulated vehicle (loopback)"

    // snippet:driver-panel-factory
    override val panel: DriverPanel = LoopbackPanel.panel
    // end-snippet

    override fun create(vehicleName: String, context: DriverContext): VehicleDriver =
        LoopbackDriver(vehicleName, context, settings, placement.takeIf { settings.placeUnpositionedVehicles })

    companion object {
        /** The factory's name, for `tcs:preferredAdapterClass`. */
        const val NAME: String = "loopback"
    }
}
