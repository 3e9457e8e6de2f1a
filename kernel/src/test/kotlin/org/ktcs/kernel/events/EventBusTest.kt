package org.ktcs.kernel.events

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import kotlinx.coroutines.channels.toList
import kotlinx.coroutines.runBlocking
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.event.UserNotification
import org.ktcs.api.event.UserNotificationEvent
import java.time.Instant

class EventBusTest : FunSpec({
    fun note(
        text: String,
    ) = UserNotificationEvent(UserNotification(null, text, NotificationLevel.INFORMATIONAL, Instant.EPOCH))

    test("an event published by a listener reaches everybody after the event being delivered") {
        val bus = EventBus()
        val first = mutableListOf<String>()
        val second = mutableListOf<String>()
        bus.listen { if ((it as UserNotificationEvent).notification.text == "a") bus.publish(note("b")) }
        bus.listen { first += (it as UserNotificationEvent).notification.text }
        bus.listen { second += (it as UserNotificationEvent).notification.text }
        val subscription = bus.subscribe()

        bus.publish(note("a"))

        first shouldBe listOf("a", "b")
        second shouldBe listOf("a", "b")
        subscription.tryReceive().getOrNull() shouldBe note("a")
        subscription.tryReceive().getOrNull() shouldBe note("b")
    }

    test("a failing listener neither keeps the event from the others nor delays the events after it") {
        val bus = EventBus()
        val later = mutableListOf<String>()
        bus.listen { if ((it as UserNotificationEvent).notification.text == "a") bus.publish(note("b")) }
        bus.listen { if ((it as UserNotificationEvent).notification.text == "a") error("listener broke on a") }
        bus.listen { later += (it as UserNotificationEvent).notification.text }
        val subscription = bus.subscribe()

        val error = shouldThrow<IllegalStateException> { bus.publish(note("a")) }
        error.message shouldBe "listener broke on a"
        later shouldBe listOf("a", "b")
        bus.publish(note("c"))

        later shouldBe listOf("a", "b", "c")
        val received = mutableListOf<KernelEvent>()
        while (true) received += subscription.tryReceive().getOrNull() ?: break
        received shouldBe listOf(note("a"), note("b"), note("c"))
    }

    test("a subscriber that falls behind is cut off with a clear exception, without slowing the others") {
        val bus = EventBus()
        val slow = bus.subscribe(capacity = 3)
        val fast = bus.subscribe(capacity = 100)
        repeat(10) { bus.publish(note("$it")) }

        val error = shouldThrow<SubscriberTooSlowException> { runBlocking { slow.toList() } }
        error.message shouldBe "event subscriber too slow: its buffer overflowed and events were lost"
        val received = mutableListOf<KernelEvent>()
        while (true) received += fast.tryReceive().getOrNull() ?: break
        received.size shouldBe 10
    }
})
