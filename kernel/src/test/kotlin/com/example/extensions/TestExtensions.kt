package com.example.extensions

import org.koin.dsl.module
import org.ktcs.api.dispatching.Dispatcher
import org.ktcs.extension.KtcsExtension

// Outside org.ktcs.kernel on purpose: the kernel tells an extension's failures apart by the extension's package.

/** Loads fine and contributes nothing. */
class WorkingExtension : KtcsExtension {
    override val name = "working"

    override fun module() = module { }
}

/** Its replacement dispatcher cannot be created, so the kernel cannot start. */
class DispatcherFailingExtension : KtcsExtension {
    override val name = "failing-dispatcher"

    override fun module() = module {
        single<Dispatcher> { error("no dispatcher licence") }
    }
}

/** Its module needs a class that no jar provides. */
class MissingClassExtension : KtcsExtension {
    override val name = "missing-class"

    override fun module() = throw NoClassDefFoundError("com/example/vendor/VendorProtocol")
}
