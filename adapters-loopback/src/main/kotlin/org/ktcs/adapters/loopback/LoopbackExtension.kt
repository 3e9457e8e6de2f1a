package org.ktcs.adapters.loopback

import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.KtcsConfig

// snippet:declared-settings
/** Contributes the loopback driver factory to the kernel, set up from the `loopback.*` settings. */
class LoopbackExtension : KtcsExtension {
    override val name: String = "loopback"

    override val settings = LoopbackConfigKeys.all

    override fun module(): Module = module {
        single { LoopbackDriverFactory(settingsFrom(getOrNull<KtcsConfig>() ?: KtcsConfig.defaults())) } bind
            VehicleDriverFactory::class
    }
    // end-snippet

    companion object {
        /** The loopback settings from kTCS's configuration. */
        fun settingsFrom(config: KtcsConfig) = LoopbackSettings(
            timeFactor = config[LoopbackConfigKeys.timeFactor],
            operatingTimeMillis = config[LoopbackConfigKeys.operatingTime],
            acceleration = config[LoopbackConfigKeys.acceleration],
            deceleration = config[LoopbackConfigKeys.deceleration],
            rechargePercentPerSecond = config[LoopbackConfigKeys.rechargeRate],
            energyDrainPercentPerKm = config[LoopbackConfigKeys.energyDrain],
            positionReportIntervalMillis = config[LoopbackConfigKeys.positionReportInterval],
            placeUnpositionedVehicles = config[LoopbackConfigKeys.placeUnpositionedVehicles],
        )
    }
}
