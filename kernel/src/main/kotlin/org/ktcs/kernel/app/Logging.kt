package org.ktcs.kernel.app

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.LoggerContext
import ch.qos.logback.classic.encoder.PatternLayoutEncoder
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.rolling.RollingFileAppender
import ch.qos.logback.core.rolling.SizeAndTimeBasedRollingPolicy
import ch.qos.logback.core.util.FileSize
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import org.ktcs.kernel.config.PersistenceSettings
import org.slf4j.LoggerFactory
import java.nio.file.Path

/** Applies the configured log level to kTCS's own loggers (logback.xml keeps libraries at WARN). */
object Logging {
    fun apply(config: KtcsConfig) {
        val logger = LoggerFactory.getLogger("org.ktcs") as? Logger ?: return
        logger.level = Level.toLevel(config[KtcsSettings.logLevel].name)
    }

    /**
     * Besides the console, logs to `<kernel.dataDirectory>/logs/ktcs.log`, rolled over daily and at
     * `log.file.maxSize`, kept for `log.file.maxHistory` days within `log.file.totalSizeCap` (maxHistory 0: no file),
     * so that an incident can be looked into after the fact. Returns the file, or `null` without one.
     */
    fun toFile(config: KtcsConfig): Path? {
        val days = config[PersistenceSettings.logFileMaxHistory]
        val root = LoggerFactory.getLogger(org.slf4j.Logger.ROOT_LOGGER_NAME) as? Logger ?: return null
        // One log file per process: a kTCS started again in the same JVM (tests) replaces the previous one's.
        root.getAppender(FILE_APPENDER)?.let {
            root.detachAppender(it)
            it.stop()
        }
        if (days == 0) return null
        val context = root.loggerContext
        val directory = Path.of(config[KtcsSettings.dataDirectory]).resolve("logs").toAbsolutePath()
        val file = directory.resolve("ktcs.log")
        val appender = RollingFileAppender<ILoggingEvent>().apply {
            this.context = context
            name = FILE_APPENDER
            this.file = file.toString()
        }
        SizeAndTimeBasedRollingPolicy<ILoggingEvent>().apply {
            this.context = context
            setParent(appender)
            fileNamePattern = directory.resolve("ktcs.%d{yyyy-MM-dd}.%i.log.gz").toString()
            setMaxFileSize(FileSize.valueOf("${config[PersistenceSettings.logFileMaxSize]}MB"))
            maxHistory = days
            setTotalSizeCap(FileSize.valueOf("${config[PersistenceSettings.logFileTotalSizeCap]}MB"))
            appender.rollingPolicy = this
            start()
        }
        appender.encoder = encoder(context)
        appender.start()
        root.addAppender(appender)
        return file
    }

    private const val FILE_APPENDER = "FILE"

    private fun encoder(context: LoggerContext) = PatternLayoutEncoder().apply {
        this.context = context
        pattern = "%d{yyyy-MM-dd'T'HH:mm:ss.SSSXXX} %-5level [%thread] %logger{36} - %msg%n"
        start()
    }

    /** A simulation reports deadlocks in its figures; one log line each would bury them. */
    fun quietNotifications() {
        (LoggerFactory.getLogger("org.ktcs.kernel.notifications") as? Logger)?.level = Level.ERROR
    }
}
