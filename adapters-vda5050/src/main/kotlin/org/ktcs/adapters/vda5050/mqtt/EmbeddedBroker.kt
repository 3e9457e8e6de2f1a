package org.ktcs.adapters.vda5050.mqtt

import com.hivemq.embedded.EmbeddedExtension
import com.hivemq.embedded.EmbeddedHiveMQ
import org.ktcs.extension.config.ConfigException
import org.slf4j.LoggerFactory
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.ExecutionException
import java.util.concurrent.TimeUnit
import java.util.concurrent.TimeoutException

/**
 * The MQTT broker kTCS starts for its VDA 5050 vehicles when no external one is configured: HiveMQ Community
 * Edition, in this process, listening on [bindAddress]:[port]. Its sessions, queues and retained messages live in
 * memory: they end with kTCS anyway, and file persistence only costs CPU per message. Only its configuration goes
 * to a temporary folder. [extension] (if any) runs inside it, e.g. the driver's [InProcessLink].
 */
class EmbeddedBroker(
    private val bindAddress: String,
    private val port: Int,
    private val extension: EmbeddedExtension? = null,
) : AutoCloseable {
    private val log = LoggerFactory.getLogger(EmbeddedBroker::class.java)
    private val home: Path = Files.createTempDirectory("ktcs-mqtt-")
    private var broker: EmbeddedHiveMQ? = null

    /** Starts the broker; an address or port it cannot use is a [ConfigException] naming the setting. */
    fun start() {
        try {
            BindCheck.check(bindAddress, port)
        } catch (error: ConfigException) {
            home.toFile().deleteRecursively()
            throw error
        }
        val config = Files.createDirectories(home.resolve("conf"))
        Files.writeString(config.resolve("config.xml"), configXml())
        val started = EmbeddedHiveMQ.builder()
            .withConfigurationFolder(config)
            .withDataFolder(Files.createDirectories(home.resolve("data")))
            .withExtensionsFolder(Files.createDirectories(home.resolve("extensions")))
            .withoutLoggingBootstrap()
            .let { builder -> extension?.let(builder::withEmbeddedExtension) ?: builder }
            .build()
        val problem = try {
            started.start().get(START_SECONDS, TimeUnit.SECONDS)
            null
        } catch (error: ExecutionException) {
            log.warn("embedded MQTT broker failed to start", error.cause)
            error.cause?.message ?: error.cause?.javaClass?.simpleName
        } catch (_: TimeoutException) {
            "it did not start within $START_SECONDS s"
        }
        if (problem != null) {
            runCatching { started.close() }
            home.toFile().deleteRecursively()
            throw ConfigException(
                "the embedded MQTT broker could not start on $bindAddress:$port (${BindCheck.BIND_ADDRESS_KEY}, ${BindCheck.PORT_KEY}): $problem",
            )
        }
        broker = started
        log.info("embedded MQTT broker listening on {}:{}", bindAddress, port)
    }

    /** How many PUBLISH packets the broker has received from its clients since it started (HiveMQ's own counter). */
    fun publishesReceived(): Long = broker?.metricRegistry?.counters?.get(INCOMING_PUBLISHES)?.count ?: 0L

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
            <persistence>
                <mode>in-memory</mode>
            </persistence>
            <anonymous-usage-statistics>
                <enabled>false</enabled>
            </anonymous-usage-statistics>
        </hivemq>
    """.trimIndent()

    private companion object {
        const val START_SECONDS = 60L
        const val INCOMING_PUBLISHES = "com.hivemq.messages.incoming.publish.count"
    }
}
