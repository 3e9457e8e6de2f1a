package org.ktcs.kernel.app

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.LoggerContext
import ch.qos.logback.classic.encoder.PatternLayoutEncoder
import ch.qos.logback.classic.spi.Configurator
import ch.qos.logback.classic.spi.ConfiguratorRank
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.ConsoleAppender
import ch.qos.logback.core.spi.ContextAwareBase

/**
 * kTCS's Logback configuration in code, the same as `logback.xml` (which stays the template for a configuration of
 * one's own; `ConsoleLoggingTest` keeps the two equal): reading the XML took Logback's Joran machinery and the JDK's
 * XML parser, 500 classes at start-up. A configuration of one's own (`-Dlogback.configurationFile` naming another
 * file, or a `logback-test.xml` on the class path) is Logback's to read, as before.
 */
@ConfiguratorRank(ConfiguratorRank.CUSTOM_HIGH_PRIORITY)
class ConsoleLogging :
    ContextAwareBase(),
    Configurator {
    override fun configure(context: LoggerContext): Configurator.ExecutionStatus {
        if (anotherConfiguration()) return Configurator.ExecutionStatus.NEUTRAL
        val encoder = PatternLayoutEncoder().apply {
            this.context = context
            pattern = PATTERN
            start()
        }
        val console = ConsoleAppender<ILoggingEvent>().apply {
            this.context = context
            name = "CONSOLE"
            this.encoder = encoder
            start()
        }
        context.getLogger("org.ktcs").level = Level.INFO
        // Any client can fail a TLS handshake: not worth a warning with a stack trace each time.
        context.getLogger("io.netty.handler.ssl").level = Level.ERROR
        context.getLogger(Logger.ROOT_LOGGER_NAME).apply {
            level = Level.WARN
            addAppender(console)
        }
        return Configurator.ExecutionStatus.DO_NOT_INVOKE_NEXT_IF_ANY
    }

    private fun anotherConfiguration(): Boolean {
        val named = System.getProperty("logback.configurationFile")
        val own = ConsoleLogging::class.java.getResource("/logback.xml")?.toString()
        return (named != null && named != own) || ConsoleLogging::class.java.getResource("/logback-test.xml") != null
    }

    internal companion object {
        const val PATTERN = "%d{yyyy-MM-dd'T'HH:mm:ss.SSSXXX} %-5level %logger{0} - %msg%n"
    }
}
