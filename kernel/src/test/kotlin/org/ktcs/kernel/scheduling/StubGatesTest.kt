package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

// The two-way corridor W = A = B = C = E (inner points A, B, C), entered at E from Q and left at E to Z, with a station
// stub S beside B and a second stub T beside C.
private val twoStubs = plant(
    "X-W", "W-Y", "W-A", "A-W", "A-B", "B-A", "B-C", "C-B", "C-E", "E-C", "E-Z", "Q-E", "B-S", "S-B", "C-T", "T-C",
)

/**
 * A vehicle that drove into a station stub keeps the corridor's way in for the way it leaves (a gate) only as long as
 * it may leave: held back by the traffic rule for [TrafficTimers.HELD_BACK_REPORT_MILLIS], it lets the vehicles
 * heading the other way go first.
 */
class StubGatesTest : FunSpec({
    test("two vehicles in stubs bound each past the other's: the one held back opens its gate after the report delay") {
        val f = SchedulerFixture(twoStubs)
        val (inS, inT) = f.client("inS") to f.client("inT")
        f.scheduler.allocateNow(inS, setOf("S"))
        // inT stands in T, bound for S: asking for its station in T (the operation), it takes the gate towards W.
        f.scheduler.allocateNow(inT, setOf("T"))
        f.scheduler.claim(
            inT,
            listOf(setOf("T")) + listOf("T-C", "C-B", "B-S").map {
                setOf(it, it.substringAfter("-"))
            },
        )
        f.allocate(inT, "T")
        inT.granted shouldContainExactly listOf(setOf("T"))

        // inS leaves S towards E, past T's mouth: the way inT will leave keeps it out of the corridor.
        f.scheduler.claim(inS, listOf("S-B", "B-C", "C-E", "E-Z").map { setOf(it, it.substringAfter("-")) })
        f.allocate(inS, "S-B", "B")
        inS.granted.shouldBeEmpty()
        // inT may not leave either: it would stand in inS's way with S, where it is bound, still taken.
        f.allocate(inT, "T-C", "C")
        f.scheduler.grantWaitOf("inT").first shouldBe GrantWait.LOCAL_RULE
        // A change elsewhere retries the grants held back, just before the report delay: the gate stays.
        f.clock.advance(TrafficTimers.HELD_BACK_REPORT_MILLIS - 1)
        f.scheduler.allocateNow(f.client("bystander"), setOf("Y"))
        f.clock.drain()
        f.scheduler.grantWaitOf("inT").first shouldBe GrantWait.LOCAL_RULE
        inS.granted.shouldBeEmpty()

        // Held back for the report delay, inT's gate opens at the next retry (the watchdog's, past the park patience).
        f.clock.advance(TrafficTimers.PARK_TEST_PATIENCE_MILLIS)
        f.scheduler.retryOverdue()
        f.clock.drain()
        inS.granted shouldContainExactly listOf(setOf("S-B", "B"))
        inT.granted shouldContainExactly listOf(setOf("T"))
    }
})
