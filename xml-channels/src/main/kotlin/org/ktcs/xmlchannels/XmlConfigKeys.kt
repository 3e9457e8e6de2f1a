package org.ktcs.xmlchannels

import org.ktcs.extension.config.intSetting
import org.ktcs.extension.config.longSetting
import org.ktcs.extension.config.stringSetting

/** The XML channels' configuration keys (`xml.*`), declared by [XmlChannelsExtension]; defaults are openTCS 4.x's. */
object XmlConfigKeys {
    private const val MAX_PORT = 65535

    val ordersPort =
        intSetting("xml.orders.port", 55555, 0..MAX_PORT, "TCP port of the XML order channel (0: any free port).")
    val statusPort =
        intSetting("xml.status.port", 44444, 0..MAX_PORT, "TCP port of the XML status channel (0: any free port).")
    val bindAddress =
        stringSetting("xml.bindAddress", "0.0.0.0", "Address the XML order and status channels listen on.")
    val ordersIdleTimeout = longSetting(
        "xml.orders.idleTimeout",
        10_000,
        1L..3_600_000L,
        "Milliseconds an XML order channel client has to send its whole telegram; a slower one is closed without a " +
            "receipt.",
    )
    val ordersInputLimit =
        intSetting("xml.orders.inputLimit", 102_400, 1..67_108_864, "The largest XML order telegram, in bytes.")
    val ordersMaxConnections = intSetting(
        "xml.orders.maxConnections",
        100,
        1..100_000,
        "XML order channel connections served at once; more are refused with a line saying so.",
    )
    val statusSeparator =
        stringSetting("xml.status.separator", "|", "Written after every message on the XML status channel.")
    val statusBufferSize = intSetting(
        "xml.status.bufferSize",
        1000,
        1..1_000_000,
        "Status messages queued for one client; a client that falls further behind is dropped.",
    )
    val statusMaxConnections = intSetting(
        "xml.status.maxConnections",
        100,
        1..100_000,
        "XML status channel clients served at once; more are refused with a line saying so.",
    )
    val scriptsDirectory =
        stringSetting("xml.scriptsDirectory", "scripts", "Directory of the .tcs batch scripts that XML telegrams name.")

    val all = listOf(
        ordersPort,
        statusPort,
        bindAddress,
        ordersIdleTimeout,
        ordersInputLimit,
        ordersMaxConnections,
        statusSeparator,
        statusBufferSize,
        statusMaxConnections,
        scriptsDirectory,
    )
}
