package org.ktcs.kernel.app

import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.LoggerContext
import ch.qos.logback.classic.encoder.PatternLayoutEncoder
import ch.qos.logback.classic.joran.JoranConfigurator
import ch.qos.logback.classic.spi.Configurator
import ch.qos.logback.core.OutputStreamAppender
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

/** The configuration in code is logback.xml's, which users copy for a configuration of their own. */
class ConsoleLoggingTest : FunSpec({
    fun describe(context: LoggerContext): List<String> {
        val loggers = listOf("org.ktcs", "io.netty.handler.ssl", Logger.ROOT_LOGGER_NAME)
            .map { "$it=${context.getLogger(it).level}" }
        val appenders = context.getLogger(Logger.ROOT_LOGGER_NAME).iteratorForAppenders().asSequence().map {
            "${it.name} ${it.javaClass.simpleName} ${((it as OutputStreamAppender).encoder as PatternLayoutEncoder).pattern}"
        }
        return loggers + appenders
    }

    test("configures what logback.xml configures") {
        val fromXml = LoggerContext().also { context ->
            JoranConfigurator().apply { this.context = context }
                .doConfigure(checkNotNull(ConsoleLogging::class.java.getResource("/logback.xml")))
        }
        val inCode = LoggerContext()
        ConsoleLogging().apply { context = inCode }.configure(inCode) shouldBe
            Configurator.ExecutionStatus.DO_NOT_INVOKE_NEXT_IF_ANY

        describe(inCode) shouldBe describe(fromXml)
        describe(inCode).last() shouldBe "CONSOLE ConsoleAppender ${ConsoleLogging.PATTERN}"
    }

    test("leaves a configuration file of one's own to Logback") {
        val previous = System.setProperty("logback.configurationFile", "my-logback.xml")
        try {
            val context = LoggerContext()
            ConsoleLogging().apply { this.context = context }.configure(context) shouldBe
                Configurator.ExecutionStatus.NEUTRAL
        } finally {
            if (previous == null) {
                System.clearProperty(
                    "logback.configurationFile",
                )
            } else {
                System.setProperty("logback.configurationFile", previous)
            }
        }
    }
})
