package org.ktcs.adapters.vda5050

import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.koin.dsl.onClose
import org.ktcs.adapters.vda5050.mqtt.BrokerSettings
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.config.KtcsConfig

/**
 * Contributes the VDA 5050 driver factory, set up from the `vda5050.*` settings. The
 * driver's one file on the extension SPI; the broker (and its embedded server) stops with the kernel.
 */
class Vda5050Extension : KtcsExtension {
    override val name: String = "vda5050"

    override val settings = Vda5050Settings.all

    override fun module(): Module = module {
        single { Vda5050Broker(settingsFrom(getOrNull<KtcsConfig>() ?: KtcsConfig.defaults())) } onClose { it?.close() }
        single { Vda5050DriverFactory(settingsFrom(getOrNull<KtcsConfig>() ?: KtcsConfig.defaults()), get()) } bind
            VehicleDriverFactory::class
    }

    companion object {
        /** The broker settings from kTCS's configuration. */
        fun settingsFrom(config: KtcsConfig) = BrokerSettings(
            url = config[Vda5050Settings.brokerUrl],
            embeddedBindAddress = config[Vda5050Settings.embeddedBindAddress],
            embeddedPort = config[Vda5050Settings.embeddedPort],
            username = config[Vda5050Settings.username],
            password = config[Vda5050Settings.password],
            mapId = config[Vda5050Settings.mapId],
            implementation = config[Vda5050Settings.embeddedImplementation],
            embeddedBatchMillis = config[Vda5050Settings.embeddedBatchMillis].toLong(),
        )
    }
}
