package org.ktcs.xmlchannels

import org.koin.core.module.Module
import org.ktcs.extension.KtcsExtension

/** Contributes openTCS's XML order and status channels on TCP to the kernel. */
class XmlChannelsExtension : KtcsExtension {
    override val name: String = "xml-channels"

    override val settings = XmlConfigKeys.all

    override fun module(): Module = xmlChannelsModule()
}
