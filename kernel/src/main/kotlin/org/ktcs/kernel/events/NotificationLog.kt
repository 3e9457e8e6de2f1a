package org.ktcs.kernel.events

import org.ktcs.api.event.UserNotification

/** The most recent user notifications, read-only; notifications are published through the kernel's operations. */
fun interface NotificationLog {
    fun recent(): List<UserNotification>
}
