package org.ktcs.kernel.events

import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.event.UserNotification
import org.ktcs.api.event.UserNotificationEvent
import org.ktcs.api.kernel.KernelClock
import org.slf4j.LoggerFactory

/** Publishes user notifications, logs them, and keeps the most recent ones. Confined to the kernel context. */
class Notifications(private val events: EventBus, private val clock: KernelClock, private val capacity: Int = 1000) :
    NotificationLog {
    private val log = LoggerFactory.getLogger("org.ktcs.kernel.notifications")
    private val recent = ArrayDeque<UserNotification>()

    fun publish(source: String?, level: NotificationLevel, text: String) {
        publish(UserNotification(source, text, level, clock.now()))
    }

    fun publish(notification: UserNotification) {
        if (recent.size == capacity) recent.removeFirst()
        recent.addLast(notification)
        val line = "notification level=${notification.level} source=${notification.source ?: "-"}: ${notification.text}"
        if (notification.level == NotificationLevel.IMPORTANT) log.warn(line) else log.info(line)
        events.publish(UserNotificationEvent(notification))
    }

    override fun recent(): List<UserNotification> = recent.toList()

    /** Puts back the notifications of a previous run, oldest first, without publishing them again. */
    fun restore(notifications: List<UserNotification>) {
        events.assertConfined { "Notifications.restore" }
        notifications.takeLast(capacity).forEach {
            if (recent.size == capacity) recent.removeFirst()
            recent.addLast(it)
        }
    }
}
