package org.ktcs.xmlchannels

import org.ktcs.extension.config.KtcsConfig
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds

/**
 * How the XML channels run; the defaults are those of [XmlConfigKeys], openTCS 4.x's (`xmlhostinterface.*`).
 *
 * @property idleTimeout the deadline for a whole order telegram: a connection that has not sent it completely by then
 *   is closed without a receipt (openTCS applied it per read, so a client trickling bytes held a thread for good).
 * @property inputLimit the most bytes an order telegram may have.
 * @property ordersMaxConnections order channel connections served at once; more are refused with a line saying so.
 * @property statusMaxConnections status channel clients served at once; more are refused with a line saying so.
 * @property statusSeparator written after every status message.
 * @property statusBufferSize status messages queued for one client; a client that falls further behind is dropped.
 */
data class XmlChannelSettings(
    val bindAddress: String = XmlConfigKeys.bindAddress.default,
    val ordersPort: Int = XmlConfigKeys.ordersPort.default,
    val statusPort: Int = XmlConfigKeys.statusPort.default,
    val idleTimeout: Duration = XmlConfigKeys.ordersIdleTimeout.default.milliseconds,
    val inputLimit: Int = XmlConfigKeys.ordersInputLimit.default,
    val statusSeparator: String = XmlConfigKeys.statusSeparator.default,
    val scriptsDirectory: Path = Path.of(XmlConfigKeys.scriptsDirectory.default),
    val statusBufferSize: Int = XmlConfigKeys.statusBufferSize.default,
    val ordersMaxConnections: Int = XmlConfigKeys.ordersMaxConnections.default,
    val statusMaxConnections: Int = XmlConfigKeys.statusMaxConnections.default,
) {
    init {
        require(idleTimeout.isPositive()) { "idle timeout must be positive, not $idleTimeout" }
        require(inputLimit > 0) { "input limit must be positive, not $inputLimit" }
        require(statusSeparator.isNotEmpty()) { "the status separator must not be empty" }
        require(statusBufferSize > 0) { "status buffer size must be positive, not $statusBufferSize" }
        require(ordersMaxConnections > 0) {
            "order channel connection limit must be positive, not $ordersMaxConnections"
        }
        require(statusMaxConnections > 0) {
            "status channel connection limit must be positive, not $statusMaxConnections"
        }
    }

    companion object {
        /** The settings from kTCS's `xml.*` configuration keys. */
        fun from(config: KtcsConfig) = XmlChannelSettings(
            bindAddress = config[XmlConfigKeys.bindAddress],
            ordersPort = config[XmlConfigKeys.ordersPort],
            statusPort = config[XmlConfigKeys.statusPort],
            idleTimeout = config[XmlConfigKeys.ordersIdleTimeout].milliseconds,
            inputLimit = config[XmlConfigKeys.ordersInputLimit],
            statusSeparator = config[XmlConfigKeys.statusSeparator],
            scriptsDirectory = Path.of(config[XmlConfigKeys.scriptsDirectory]),
            statusBufferSize = config[XmlConfigKeys.statusBufferSize],
            ordersMaxConnections = config[XmlConfigKeys.ordersMaxConnections],
            statusMaxConnections = config[XmlConfigKeys.statusMaxConnections],
        )
    }
}
