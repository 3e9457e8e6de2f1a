package org.ktcs.xmlchannels

import org.ktcs.kernel.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * How the XML channels run; the defaults are openTCS 4.x's (`xmlhostinterface.*`).
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
    val bindAddress: String = "0.0.0.0",
    val ordersPort: Int = 55555,
    val statusPort: Int = 44444,
    val idleTimeout: Duration = 10.seconds,
    val inputLimit: Int = 100 * 1024,
    val statusSeparator: String = "|",
    val scriptsDirectory: Path = Path.of("scripts"),
    val statusBufferSize: Int = 1000,
    val ordersMaxConnections: Int = 100,
    val statusMaxConnections: Int = 100,
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
            bindAddress = config[KtcsSettings.xmlBindAddress],
            ordersPort = config[KtcsSettings.xmlOrdersPort],
            statusPort = config[KtcsSettings.xmlStatusPort],
            idleTimeout = config[KtcsSettings.xmlOrdersIdleTimeout].milliseconds,
            inputLimit = config[KtcsSettings.xmlOrdersInputLimit],
            statusSeparator = config[KtcsSettings.xmlStatusSeparator],
            scriptsDirectory = Path.of(config[KtcsSettings.xmlScriptsDirectory]),
            statusBufferSize = config[KtcsSettings.xmlStatusBufferSize],
            ordersMaxConnections = config[KtcsSettings.xmlOrdersMaxConnections],
            statusMaxConnections = config[KtcsSettings.xmlStatusMaxConnections],
        )
    }
}
