package org.ktcs.xmlchannels

import java.nio.file.Files
import java.nio.file.Path
import java.time.Clock
import java.time.Instant
import java.time.ZoneOffset
import kotlin.time.Duration.Companion.milliseconds

/** Settings for tests: free ports on the loopback interface, a fresh scripts directory, short timeouts. */
fun testSettings(
    scripts: Path = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-scripts"),
) = XmlChannelSettings(
    bindAddress = "127.0.0.1",
    ordersPort = 0,
    statusPort = 0,
    idleTimeout = 300.milliseconds,
    inputLimit = 100 * 1024,
    scriptsDirectory = scripts,
    statusBufferSize = 8,
)

val fixedClock: Clock = Clock.fixed(Instant.parse("2016-11-24T10:41:41.875Z"), ZoneOffset.ofHours(1))

/** Runs [block] with started channels over [services], and stops them afterwards. */
suspend fun <T> withChannels(
    services: FakeKernelServices = FakeKernelServices(),
    settings: XmlChannelSettings = testSettings(),
    block: suspend (XmlChannels) -> T,
): T = XmlChannels(services, settings, fixedClock).start().use { block(it) }
