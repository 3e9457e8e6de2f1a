package org.ktcs.e2e.extensions

import org.koin.core.module.Module
import org.koin.core.qualifier.named
import org.koin.dsl.module
import org.ktcs.extension.KtcsExtension
import org.ktcs.extension.ServedAddresses
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.extension.config.stringSetting

/**
 * An extension with a setting of its own, which it shows in the ready line. Not listed in this module's services
 * file: ExtensionDirectoryTest packs it into a jar of its own for the extensions directory of `./ktcs`.
 */
class GreetingExtension : KtcsExtension {
    override val name = "greeting"

    override val settings = listOf(GREETING)

    override fun module(): Module = module {
        single<ServedAddresses>(named("greeting")) {
            ServedAddresses { listOf("greeting ${get<KtcsConfig>()[GREETING]}") }
        }
    }

    companion object {
        val GREETING = stringSetting("greeting.text", "hello", "What the greeting extension shows in the ready line.")
    }
}
