package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.simulation.TrafficGrid
import org.ktcs.kernel.simulation.WarehousePlant

// The two-way corridor W = A = B = C = E with a station stub S beside B; W and E are junctions with one-way lanes
// (X -> W -> Y, Q -> E -> Z), so the corridor's inner points are A, B and C.
private val corridorPaths = arrayOf(
    "X-W", "W-Y", "W-A", "A-W", "A-B", "B-A", "B-C", "C-B", "C-E", "E-C", "E-Z", "Q-E", "B-S", "S-B",
)
private val corridor = plant(*corridorPaths)

/** The implicit same-direction records of two-way corridors ([Corridors]), as the scheduler applies them. */
class CorridorsTest : FunSpec({
    test("a corridor is a chain of two-way points between junctions, without its stubs and ends") {
        val found = Corridors(corridor).blocks

        found.map { it.members }.single() shouldContainExactlyInAnyOrder
            listOf("A", "B", "C", "W-A", "A-W", "A-B", "B-A", "B-C", "C-B", "C-E", "E-C")
    }

    test("a warehouse's aisles are corridors; a one-way grid has none") {
        val warehouse = WarehousePlant(aisles = 3, depth = 6, vehicles = 2).build()

        val corridors = Corridors(warehouse)
        // Aisle 01 between its junctions S-002 and N-002, and one chain round each outer aisle and its corners.
        corridors.blocks.size shouldBe 3
        val aisle = corridors.blockOf("A-01-02")!!.members.filter { it.matches(Regex("A-01-\\d\\d")) }
        aisle shouldContainExactlyInAnyOrder listOf("A-01-01", "A-01-02", "A-01-03", "A-01-04")
        corridors.blockOf("Stub-01-01") shouldBe null
        corridors.blockOf("S-002") shouldBe null
        Corridors(TrafficGrid(4, 4, 3).build()).isEmpty shouldBe true
    }

    test("a vehicle coming in at the other end waits until the corridor is empty") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.place(v1, "W", "W-A", "A-B")
        f.place(v2, "E", "E-C", "C-B")
        f.allocate(v1, "W-A", "A")

        f.allocate(v2, "E-C", "C")
        v2.granted.shouldBeEmpty()

        f.free(v1, "W-A", "A")
        v2.granted shouldContainExactly listOf(setOf("E-C", "C"))
    }

    test("a vehicle coming in at the same end follows the one inside") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.place(v1, "W", "W-A", "A-B")
        f.allocate(v1, "W-A", "A")
        f.allocate(v1, "A-B", "B")
        f.free(v1, "W", "W-A", "A")

        f.place(v2, "W", "W-A", "A-B")
        f.allocate(v2, "W-A", "A")

        v2.granted shouldContainExactly listOf(setOf("W-A", "A"))
    }

    test("out of a stub a vehicle comes in like any other, heading where its route goes next") {
        val f = SchedulerFixture(corridor)
        val (v1, against, along) = Triple(f.client("v1"), f.client("against"), f.client("along"))
        // v1 stands at A, having come in at W; the point B beside the stub is free.
        f.place(v1, "W", "W-A")
        f.allocate(v1, "W-A", "A")
        f.free(v1, "W")
        f.place(against, "S", "S-B", "B-A")

        f.allocate(against, "S-B", "B")
        against.granted.shouldBeEmpty()

        f.scheduler.freeAll(against)
        f.place(along, "S", "S-B", "B-C")
        f.allocate(along, "S-B", "B")
        along.granted shouldContainExactly listOf(setOf("S-B", "B"))
    }

    test("a vehicle bound into the corridor against its users does not take the junction they leave by") {
        val f = SchedulerFixture(corridor)
        val (inside, outside) = f.client("inside") to f.client("outside")
        // inside came in at E and drives towards W; outside wants in at W.
        f.place(inside, "E", "E-C", "C-B", "B-A", "A-W")
        f.allocate(inside, "E-C", "C")
        f.free(inside, "E")
        f.place(outside, "X", "X-W", "W-A")

        f.allocate(outside, "X-W", "W")
        outside.granted.shouldBeEmpty()

        f.free(inside, "E-C", "C")
        outside.granted shouldContainExactly listOf(setOf("X-W", "W"))
    }

    test("a vehicle granted the junction it comes in by keeps the corridor's direction until it leaves that junction") {
        val (f, outside, bay) = bayBehindAGate()

        f.allocate(bay, "S-B", "B")
        bay.granted.shouldBeEmpty()
        f.scheduler.waitsFor()["bay"].orEmpty().keys shouldContainExactly setOf("outside")

        // outside changes its mind at the junction and drives on to Y: once it left W the corridor is free again.
        f.scheduler.claim(outside, listOf(setOf("W-Y", "Y")))
        f.allocate(outside, "W-Y", "Y")
        bay.granted.shouldBeEmpty()
        f.free(outside, "X-W", "W")
        bay.granted shouldContainExactly listOf(setOf("S-B", "B"))
    }

    test("a vehicle left without a route at a corridor's end keeps nobody out of the corridor") {
        val (f, outside, bay) = bayBehindAGate()
        f.allocate(bay, "S-B", "B")

        // Its order ended (withdrawn) while it stood at W: it stays on W but is bound into the corridor no more.
        f.scheduler.unclaim(outside)
        f.clock.drain()

        bay.granted shouldContainExactly listOf(setOf("S-B", "B"))
    }

    test("a vehicle turning into a bay beside a corridor is judged by the way out of the bay, not by its way on") {
        val f = SchedulerFixture(corridor)
        // bay drives from A to B and covers B until it is all the way into S; it turns back there and heads for W,
        // against the follower behind it, which heads for E and waits for B.
        val bay = object : RecordingClient("bay") {
            override fun heldAfter(resources: Set<String>) = if ("S" in resources) setOf("B") else emptySet()
        }
        val follower = f.client("follower")
        f.place(bay, "A", "A-B", "B-S", "S-B", "B-A", "A-W", "W-Y")
        f.allocate(bay, "A-B", "B")
        f.free(bay, "A")
        f.place(follower, "A", "A-B", "B-C", "C-E", "E-Z")

        f.allocate(bay, "B-S", "S")

        // In the bay it frees B, the follower drives on, and the bay comes out once the corridor lets it head for W.
        bay.granted shouldContainExactly listOf(setOf("A-B", "B"), setOf("B-S", "S"))
    }
})

// The corridor with a second bay T beside A: a vehicle stopping there waits only for the way out of it, so deadlock
// avoidance alone would let "bay" come out of S towards W while "outside", granted W, is bound in towards E.
private fun bayBehindAGate(): Triple<SchedulerFixture, RecordingClient, RecordingClient> {
    val f = SchedulerFixture(plant(*corridorPaths, "A-T", "T-A"))
    val (outside, bay) = f.client("outside") to f.client("bay")
    f.place(outside, "X", "X-W", "W-A", "A-B")
    f.place(bay, "S", "S-B", "B-A", "A-T", "T-A", "A-W")
    f.allocate(outside, "X-W", "W")
    outside.granted shouldContainExactly listOf(setOf("X-W", "W"))
    return Triple(f, outside, bay)
}

// Places [client] at [point] and has it claim a route of the paths named `SOURCE-DESTINATION` in [paths].
private fun SchedulerFixture.place(client: RecordingClient, point: String, vararg paths: String) {
    scheduler.allocateNow(client, setOf(point))
    scheduler.claim(client, paths.map { setOf(it, it.substringAfter("-")) })
}
