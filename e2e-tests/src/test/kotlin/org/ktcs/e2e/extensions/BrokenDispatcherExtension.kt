package org.ktcs.e2e.extensions

import org.koin.core.module.Module
import org.koin.dsl.module
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.extension.KtcsExtension

/**
 * An extension whose dispatcher cannot be created. Not listed in this module's services file: ExtensionDirectoryTest
 * packs it into a jar of its own for the extensions directory of `./ktcs`.
 */
class BrokenDispatcherExtension : KtcsExtension {
    override val name = "broken-dispatcher"

    override fun module(): Module = module {
        single<Dispatcher> { error("the dispatcher licence has expired") }
    }
}
