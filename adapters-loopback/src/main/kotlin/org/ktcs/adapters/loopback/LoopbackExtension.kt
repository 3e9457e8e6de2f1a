package org.ktcs.adapters.loopback

import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.extension.KtcsExtension

/** Contributes the loopback driver factory to the kernel, set up from the `loopback.*` settings. */
class LoopbackExtension : KtcsExtension {
    override val name: String = "loopback"

    override fun module(): Module = module {
        single { LoopbackDriverFactory(settingsFrom(getOrNull<KtcsConfig>() ?: KtcsConfig.defaults())) } bind
            VehicleDriverFactory::class
    }

    companion object {
        /** The loopback settings from kTCS's configuration. */
        fun settingsFrom(config: KtcsConfig) = LoopbackSettings(
            timeFactor = config[KtcsSettings.loopbackTimeFactor],
            operatingTimeMillis = config[KtcsSettings.loopbackOperatingTime],
            acceleration = config[KtcsSettings.loopbackAcceleration],
            deceleration = config[KtcsSettings.loopbackDeceleration],
            rechargePercentPerSecond = config[KtcsSettings.loopbackRechargeRate],
            energyDrainPercentPerKm = config[KtcsSettings.loopbackEnergyDrain],
            positionReportIntervalMillis = config[KtcsSettings.loopbackPositionReportInterval],
            placeUnpositionedVehicles = config[KtcsSettings.loopbackPlaceUnpositionedVehicles],
        )
    }
}
