package org.ktcs.adapters.vda5050

import ch.qos.logback.classic.Logger
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.read.ListAppender
import org.ktcs.api.event.UserNotificationEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.kernel.core.KernelCore
import org.slf4j.LoggerFactory
import java.util.Collections

/** The user notifications the kernel publishes from now on, as text. */
fun notificationsOf(kernel: KernelCore): List<String> {
    val texts = Collections.synchronizedList(mutableListOf<String>())
    kernel.events.listen { event -> if (event is UserNotificationEvent) texts += event.notification.text }
    return texts
}

/**
 * After every vehicle event: resources held by two vehicles at once, and points two vehicles report standing on.
 * Runs in the kernel context, so it sees every intermediate state.
 */
fun exclusivityViolations(kernel: KernelCore): List<String> {
    val violations = Collections.synchronizedList(mutableListOf<String>())
    kernel.events.listen { event ->
        if (event !is VehicleEvent) return@listen
        val vehicles = kernel.plant.model().vehicles
        val holders = vehicles.flatMap { v -> v.allocatedResources.flatten().toSet().map { it to v.name } }
            .groupBy({ it.first }, { it.second }).filterValues { it.size > 1 }
        holders.forEach { (resource, names) -> violations += "$resource held by $names" }
        vehicles.filter { it.currentPosition != null }.groupBy { it.currentPosition }.filterValues { it.size > 1 }
            .forEach { (point, vs) -> violations += "$point occupied by ${vs.map { it.name }}" }
    }
    return violations
}

/** The lines logged by [loggerName] from now on. */
fun logLinesOf(loggerName: String): List<String> {
    val appender = ListAppender<ILoggingEvent>().apply { start() }
    (LoggerFactory.getLogger(loggerName) as Logger).addAppender(appender)
    return object : AbstractList<String>() {
        override val size: Int get() = synchronized(appender.list) { appender.list.size }

        override fun get(index: Int): String = synchronized(appender.list) { appender.list[index].formattedMessage }
    }
}
