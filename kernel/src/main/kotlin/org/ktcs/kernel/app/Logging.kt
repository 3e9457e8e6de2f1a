package org.ktcs.kernel.app

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import org.ktcs.extension.config.KtcsConfig
import org.ktcs.kernel.config.KtcsSettings
import org.slf4j.LoggerFactory

/** Applies the configured log level to kTCS's own loggers (logback.xml keeps libraries at WARN). */
object Logging {
    fun apply(config: KtcsConfig) {
        val logger = LoggerFactory.getLogger("org.ktcs") as? Logger ?: return
        logger.level = Level.toLevel(config[KtcsSettings.logLevel].name)
    }

    /** A simulation reports deadlocks in its figures; one log line each would bury them. */
    fun quietNotifications() {
        (LoggerFactory.getLogger("org.ktcs.kernel.notifications") as? Logger)?.level = Level.ERROR
    }
}
