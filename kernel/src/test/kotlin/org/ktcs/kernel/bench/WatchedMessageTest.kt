package org.ktcs.kernel.bench

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.nulls.shouldBeNull
import io.kotest.matchers.shouldBe
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.api.event.KernelEvent
import org.ktcs.api.event.NotificationLevel
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.UserNotification
import org.ktcs.api.event.UserNotificationEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.TransportOrder
import org.ktcs.api.order.TransportOrderState
import org.ktcs.kernel.web.ws.ChangedFields
import org.ktcs.kernel.web.ws.Unchanged
import org.ktcs.kernel.web.ws.WsTopics
import java.time.Instant

class WatchedMessageTest : FunSpec({
    fun sent(event: KernelEvent, omitUnchanged: Boolean): WatchedMessage {
        val unchanged = if (omitUnchanged) Unchanged.fieldsOf(event) else emptyList()
        val bytes = WsTopics.change(event)!!.eventBytes(1, withPrevious = false, unchanged = unchanged)
        return WatchedMessage.parse(bytes.decodeToString())!!
    }

    test("the bench reads a vehicle's name, point and allocations from the events kTCS sends") {
        val driving = Vehicle(
            "Vehicle-01",
            currentPosition = "Point-1",
            allocatedResources = listOf(setOf("Point-1"), setOf("Point-1 --- Point-2", "Point-2")),
            claimedResources = listOf(setOf("Point-2 --- Point-3", "Point-3")),
        )

        val message = sent(VehicleEvent(null, driving), omitUnchanged = true)

        message.type shouldBe "event"
        message.topic shouldBe "vehicles"
        message.current!!.name shouldBe "Vehicle-01"
        message.current!!.point shouldBe "Point-1"
        message.current!!.allocatedResources shouldBe
            listOf(listOf("Point-1"), listOf("Point-1 --- Point-2", "Point-2"))
    }

    test("allocations left out as unchanged read as not sent, not as none") {
        val driving = Vehicle("Vehicle-01", currentPosition = "Point-1", allocatedResources = listOf(setOf("Point-1")))

        val moved = sent(VehicleEvent(driving, driving.copy(currentPosition = null)), omitUnchanged = true)
        val released = sent(VehicleEvent(driving, driving.copy(allocatedResources = emptyList())), omitUnchanged = true)

        moved.current!!.allocatedResources.shouldBeNull()
        moved.current!!.point.shouldBeNull()
        released.current!!.allocatedResources shouldBe emptyList()
    }

    test("with onlyChanged, a vehicle that left its point reads as on none, one that did not move as not saying") {
        val driving = Vehicle("Vehicle-01", currentPosition = "Point-1", allocatedResources = listOf(setOf("Point-1")))
        fun sentChanged(event: VehicleEvent) = WatchedMessage.parse(
            WsTopics.change(event)!!.eventBytes(1, withPrevious = false, changed = ChangedFields.of(event))
                .decodeToString(),
        )!!.current!!

        val left = sentChanged(VehicleEvent(driving, driving.copy(currentPosition = null)))
        val paused = sentChanged(VehicleEvent(driving, driving.copy(paused = true)))
        val arrived = sentChanged(VehicleEvent(driving, driving.copy(currentPosition = "Point-2")))

        (left.sendsPosition to left.point) shouldBe (true to null)
        (paused.sendsPosition to paused.point) shouldBe (false to null)
        paused.allocatedResources.shouldBeNull()
        (arrived.sendsPosition to arrived.point) shouldBe (true to "Point-2")
    }

    test("allocations that lost their first steps read as the number lost") {
        val driving = Vehicle(
            "Vehicle-01",
            currentPosition = "Point-2",
            allocatedResources = listOf(setOf("Point-1"), setOf("Point-1 --- Point-2", "Point-2")),
        )
        val passed = VehicleEvent(driving, driving.copy(allocatedResources = driving.allocatedResources.drop(1)))

        val bytes = WsTopics.change(passed)!!.eventBytes(
            1,
            withPrevious = false,
            Unchanged.fieldsOf(passed),
            Unchanged.shortenedOf(passed),
        )
        val message = WatchedMessage.parse(bytes.decodeToString())!!

        message.current!!.allocatedResources.shouldBeNull()
        message.shortened shouldBe mapOf("allocatedResources" to 1)
    }

    test("an order's state is read as its name, and text that is no message as none") {
        val order = TransportOrder(
            "TOrder-01",
            emptyList(),
            state = TransportOrderState.BEING_PROCESSED,
            creationTime = Instant.EPOCH,
        )

        val message = sent(TransportOrderEvent(null, order), omitUnchanged = false)

        message.current!!.name shouldBe "TOrder-01"
        message.current!!.state!!.jsonPrimitive.content shouldBe "BEING_PROCESSED"
        WatchedMessage.parse("{\"type\":").shouldBeNull()
    }

    test("the watchdog's deadlock notifications are told apart from its moves of idle vehicles") {
        fun notification(source: String, text: String) = sent(
            UserNotificationEvent(UserNotification(source, text, NotificationLevel.IMPORTANT, Instant.EPOCH)),
            omitUnchanged = true,
        ).current!!
        val deadlock = notification(
            "deadlock watchdog",
            "deadlock: vehicles V1 -> V2 wait for each other; contested resources P1, P2",
        )
        val moved = notification(
            "deadlock watchdog",
            "vehicle V3 stood idle in the way of V1 at P7; sent to Park-01 with order Clear-01",
        )
        val other = notification("kernel", "vehicle V1 is paused")

        listOf(deadlock, moved, other).map { it.isDeadlock to it.isIdleVehicleMoved } shouldBe
            listOf(true to false, false to true, false to false)
    }
})
