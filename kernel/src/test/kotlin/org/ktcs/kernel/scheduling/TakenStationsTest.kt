package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.maps.shouldContainExactly
import io.kotest.matchers.shouldBe
import io.kotest.matchers.shouldNotBe

// The two-way corridor W = A = B = C = E (inner points A, B, C) with a station stub S beside B, entered at E from Q;
// a second stub T beside C.
private val stubbedCorridor = plant(
    "X-W", "W-Y", "W-A", "A-W", "A-B", "B-A", "B-C", "C-B", "C-E", "E-C", "E-Z", "Q-E", "B-S", "S-B", "C-T", "T-C",
)

/** A vehicle bound for a station stub another vehicle stands in waits outside the corridor ([GrantWait.STATION_TAKEN]). */
class TakenStationsTest : FunSpec({
    test("a vehicle bound for a stub another vehicle stands in is not let into the corridor until the stub is free") {
        val (f, inStub) = stubTaken()
        val newcomer = f.client("newcomer")
        // newcomer comes in at E, stops in S, turns back.
        f.place(newcomer, "Q", "Q-E", "E-C", "C-B", "B-S", "S-B", "B-C")

        f.allocate(newcomer, "Q-E", "E")

        newcomer.granted.shouldBeEmpty()
        f.scheduler.grantWaitOf("newcomer").first shouldBe GrantWait.STATION_TAKEN
        // Past the report delay the wait is one the watchdog sees: for the vehicle in the stub, by the stub.
        f.clock.advance(TrafficTimers.HELD_BACK_REPORT_MILLIS)
        f.scheduler.waitsFor()["newcomer"].orEmpty() shouldContainExactly mapOf("inStub" to setOf("S"))

        // inStub leaves towards W; once S is free, newcomer comes in.
        f.scheduler.claim(inStub, listOf(setOf("S-B", "B"), setOf("B-A", "A"), setOf("A-W", "W")))
        f.allocate(inStub, "S-B", "B")
        f.free(inStub, "S")
        newcomer.granted shouldContainExactly listOf(setOf("Q-E", "E"))
    }

    test("a vehicle bound for a free stub, or passing a taken one, comes in as before") {
        val (f, _) = stubTaken()
        val (toT, through) = f.client("toT") to f.client("through")
        f.place(toT, "Q", "Q-E", "E-C", "C-T", "T-C", "C-E", "E-Z")

        f.allocate(toT, "Q-E", "E")
        toT.granted shouldContainExactly listOf(setOf("Q-E", "E"))

        f.scheduler.freeAll(toT)
        f.place(through, "Q", "Q-E", "E-C", "C-B", "B-A", "A-W", "W-Y")
        f.allocate(through, "Q-E", "E")
        through.granted shouldContainExactly listOf(setOf("Q-E", "E"))
    }

    test("a vehicle in a stub beside the corridor is not held back by it, even bound for another taken stub") {
        val (f, _) = stubTaken()
        val inT = f.client("inT")
        // inT, beside the corridor already, is bound for S: the rule is for vehicles outside the corridor.
        f.place(inT, "T", "T-C", "C-B", "B-S", "S-B", "B-A", "A-W")

        f.allocate(inT, "T-C", "C")

        f.scheduler.grantWaitOf("inT").first shouldNotBe GrantWait.STATION_TAKEN
    }
})

// The corridor with a vehicle standing in S without a route (it operates there).
private fun stubTaken(): Pair<SchedulerFixture, RecordingClient> {
    val f = SchedulerFixture(stubbedCorridor)
    val inStub = f.client("inStub")
    f.scheduler.allocateNow(inStub, setOf("S"))
    return f to inStub
}

// Places [client] at [point] and has it claim a route of the paths named `SOURCE-DESTINATION` in [paths].
private fun SchedulerFixture.place(client: RecordingClient, point: String, vararg paths: String) {
    scheduler.allocateNow(client, setOf(point))
    scheduler.claim(client, paths.map { setOf(it, it.substringAfter("-")) })
}
