package org.ktcs.xmlchannels

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import org.slf4j.LoggerFactory

/** Records what [type]'s logger logs at WARN and above while [block] runs. */
suspend fun <T> capturingWarnings(type: Class<*>, block: suspend () -> T): Pair<T, List<String>> =
    capturing(LoggerFactory.getLogger(type) as Logger, Level.WARN, block)

/** What any logger logs at ERROR while [block] runs. */
suspend fun errorsLoggedWhile(block: suspend () -> Unit): List<String> =
    capturing(LoggerFactory.getLogger(Logger.ROOT_LOGGER_NAME) as Logger, Level.ERROR, block).second

private suspend fun <T> capturing(logger: Logger, level: Level, block: suspend () -> T): Pair<T, List<String>> {
    val appender = ListAppender<ILoggingEvent>().apply { start() }
    logger.addAppender(appender)
    try {
        val result = block()
        return result to appender.list.filter { it.level.isGreaterOrEqual(level) }.map { it.formattedMessage }
    } finally {
        logger.detachAppender(appender)
    }
}
