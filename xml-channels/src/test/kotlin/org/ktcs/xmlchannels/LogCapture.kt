package org.ktcs.xmlchannels

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import org.slf4j.LoggerFactory

/** Records what [type]'s logger logs at WARN and above while [block] runs. */
suspend fun <T> capturingWarnings(type: Class<*>, block: suspend () -> T): Pair<T, List<String>> {
    val logger = LoggerFactory.getLogger(type) as Logger
    val appender = ListAppender<ILoggingEvent>().apply { start() }
    logger.addAppender(appender)
    try {
        val result = block()
        return result to appender.list.filter { it.level.isGreaterOrEqual(Level.WARN) }.map { it.formattedMessage }
    } finally {
        logger.detachAppender(appender)
    }
}
