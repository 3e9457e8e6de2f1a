package org.ktcs.kernel.vehicles

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.event.DriverEvent
import java.time.Instant

class RecentDriverEventsTest : FunSpec({
    fun event(
        vehicle: String,
        second: Long,
    ) = DriverEvent(vehicle, "t", mapOf("n" to "$second"), Instant.ofEpochSecond(second))

    test("keeps the latest events of each vehicle, oldest first, and all vehicles' in time order") {
        val recent = RecentDriverEvents(perVehicle = 3)
        (1L..5L).forEach { recent.add(event("A", it)) }
        recent.add(event("B", 3))
        recent.of("A").map { it.timestamp.epochSecond } shouldBe listOf(3L, 4L, 5L)
        recent.of(null).map { it.vehicle to it.timestamp.epochSecond } shouldBe
            listOf("A" to 3L, "B" to 3L, "A" to 4L, "A" to 5L)
        recent.of("C").shouldBeEmpty()
        recent.clear()
        recent.of(null).shouldBeEmpty()
    }
})
