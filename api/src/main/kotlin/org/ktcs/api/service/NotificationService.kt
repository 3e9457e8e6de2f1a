package org.ktcs.api.service

import org.ktcs.api.event.UserNotification

/** Messages for the operators. */
public interface NotificationService {
    /** Publishes a notification to every client. */
    public suspend fun publish(notification: UserNotification)

    /** The most recent notifications (the kernel keeps a bounded number), oldest first. */
    public suspend fun notifications(): List<UserNotification>
}
