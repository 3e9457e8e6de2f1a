package org.ktcs.adapters.vda5050.mqtt

import com.hivemq.embedded.EmbeddedHiveMQ
import org.slf4j.LoggerFactory
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit

/**
 * The MQTT broker kTCS starts for its VDA 5050 vehicles when no external one is configured: HiveMQ Community
 * Edition, in this process, listening on [bindAddress]:[port], keeping nothing on disk beyond a temporary folder.
 */
class EmbeddedBroker(private val bindAddress: String, private val port: Int) : AutoCloseable {
    private val log = LoggerFactory.getLogger(EmbeddedBroker::class.java)
    private val home: Path = Files.createTempDirectory("ktcs-mqtt-")
    private var broker: EmbeddedHiveMQ? = null

    fun start() {
        checkPortFree()
        val config = Files.createDirectories(home.resolve("conf"))
        Files.writeString(config.resolve("config.xml"), configXml())
        val started = EmbeddedHiveMQ.builder()
            .withConfigurationFolder(config)
            .withDataFolder(Files.createDirectories(home.resolve("data")))
            .withExtensionsFolder(Files.createDirectories(home.resolve("extensions")))
            .withoutLoggingBootstrap()
            .build()
        try {
            started.start().get(START_SECONDS, TimeUnit.SECONDS)
        } catch (error: java.util.concurrent.ExecutionException) {
            runCatching { started.close() }
            throw IllegalStateException(
                "the embedded MQTT broker could not start on $bindAddress:$port: " +
                    (error.cause?.message ?: error.cause?.javaClass?.simpleName),
                error.cause,
            )
        }
        broker = started
        log.info("embedded MQTT broker listening on {}:{}", bindAddress, port)
    }

    /** HiveMQ reports a taken port only in its log: say it here, with what to change. */
    private fun checkPortFree() {
        try {
            java.net.ServerSocket(port, 1, java.net.InetAddress.getByName(bindAddress)).close()
        } catch (error: java.io.IOException) {
            throw IllegalStateException(
                "the embedded MQTT broker cannot listen on $bindAddress:$port (${error.message}); set " +
                    "vda5050.embeddedBroker.port (or vda5050.brokerUrl for an external broker)",
                error,
            )
        }
    }

    override fun close() {
        val running = broker ?: return
        broker = null
        runCatching { running.stop().get(START_SECONDS, TimeUnit.SECONDS) }
        runCatching { running.close() }
        home.toFile().deleteRecursively()
        log.info("embedded MQTT broker stopped")
    }

    private fun configXml() = """
        <?xml version="1.0"?>
        <hivemq>
            <listeners>
                <tcp-listener>
                    <port>$port</port>
                    <bind-address>$bindAddress</bind-address>
                </tcp-listener>
            </listeners>
            <anonymous-usage-statistics>
                <enabled>false</enabled>
            </anonymous-usage-statistics>
        </hivemq>
    """.trimIndent()

    private companion object {
        const val START_SECONDS = 60L
    }
}
