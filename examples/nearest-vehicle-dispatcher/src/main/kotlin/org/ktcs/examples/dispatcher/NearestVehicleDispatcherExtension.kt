package org.ktcs.examples.dispatcher

import org.koin.core.module.Module
import org.koin.dsl.module
import org.ktcs.api.dispatching.DispatchContext
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.extension.KernelDefaults
import org.ktcs.extension.KtcsExtension

// snippet:replace-dispatcher
/**
 * Replaces kTCS's dispatcher: the kernel loads extension modules after its own, so this definition of
 * [Dispatcher] wins. The default dispatcher ([KernelDefaults]) is kept inside for what this one leaves alone.
 */
class NearestVehicleDispatcherExtension : KtcsExtension {
    override val name: String = "nearest-vehicle-dispatcher"

    override fun module(): Module = module {
        single<Dispatcher> {
            NearestVehicleDispatcher(get<DispatchContext>(), get<KernelDefaults>().dispatcher())
        }
    }
}
// end-snippet
