package org.ktcs.examples.dispatcher

import org.koin.core.module.Module
import org.koin.dsl.module
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.dispatching.DefaultDispatcher
import org.ktcs.kernel.extension.KtcsExtension

// snippet:replace-dispatcher
/**
 * Replaces kTCS's dispatcher: the kernel loads extension modules after its own, so this definition of
 * [Dispatcher] wins. The default dispatcher is kept inside for what this one leaves alone.
 */
class NearestVehicleDispatcherExtension : KtcsExtension {
    override val name: String = "nearest-vehicle-dispatcher"

    override fun module(): Module = module {
        single<Dispatcher> {
            val context = get<KernelCore>().dispatchContext
            NearestVehicleDispatcher(context, DefaultDispatcher(get(), context, get()))
        }
    }
}
// end-snippet
