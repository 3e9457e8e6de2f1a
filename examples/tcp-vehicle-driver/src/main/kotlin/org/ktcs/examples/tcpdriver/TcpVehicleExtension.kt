package org.ktcs.examples.tcpdriver

import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.extension.KtcsExtension

// snippet:driver-extension
/**
 * Contributes the TCP driver to kTCS. Listed in `META-INF/services/org.ktcs.extension.KtcsExtension`, so
 * kTCS finds it in a jar in its `extensions/` directory.
 */
class TcpVehicleExtension : KtcsExtension {
    override val name: String = "tcp-vehicle-driver"

    override fun module(): Module = module {
        single { TcpVehicleDriverFactory() } bind VehicleDriverFactory::class
    }
}
// end-snippet
