package org.ktcs.xmlchannels

import org.koin.core.module.Module
import org.koin.core.qualifier.named
import org.koin.dsl.module
import org.koin.dsl.onClose
import org.ktcs.extension.ServedAddresses
import org.ktcs.extension.config.KtcsConfig

/**
 * The XML channels' Koin definitions: they start listening when the kernel's Koin application is created (the
 * kernel creates `createdAtStart` definitions then) and stop when it is closed.
 */
fun xmlChannelsModule(settings: (KtcsConfig) -> XmlChannelSettings = XmlChannelSettings::from): Module = module {
    single(createdAtStart = true) {
        XmlChannels(get(), settings(getOrNull<KtcsConfig>() ?: KtcsConfig.defaults())).start()
    } onClose { it?.close() }
    // Named: every extension may add addresses, and Koin keeps only the last unnamed definition of a type.
    single<ServedAddresses>(named("xml-channels")) {
        ServedAddresses {
            val channels = get<XmlChannels>()
            val host = settings(getOrNull<KtcsConfig>() ?: KtcsConfig.defaults()).bindAddress
            listOf("XML orders tcp://$host:${channels.ordersPort}", "XML status tcp://$host:${channels.statusPort}")
        }
    }
}
