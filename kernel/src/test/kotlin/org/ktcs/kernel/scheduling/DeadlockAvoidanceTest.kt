package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.longs.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.Link
import org.ktcs.api.model.Location

/** The traffic rule (developer's guide, section 12) on the directed square A → B → C → D → A with a way in E → D. */
class DeadlockAvoidanceTest : FunSpec({
    val square = plant("A-B", "B-C", "C-D", "D-A", "E-D", "B-F")

    fun squareWithThree(): Pair<SchedulerFixture, List<RecordingClient>> {
        val f = SchedulerFixture(square)
        val vehicles = listOf("v1" to "A", "v2" to "B", "v3" to "C").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        // Each one wants to go one step on around the square.
        f.scheduler.claim(vehicles[0], listOf(setOf("A-B", "B"), setOf("B-F", "F")))
        f.scheduler.claim(vehicles[1], listOf(setOf("B-C", "C"), setOf("C-D", "D")))
        f.scheduler.claim(vehicles[2], listOf(setOf("C-D", "D"), setOf("D-A", "A")))
        return f to vehicles
    }

    test("a vehicle entering the last free point of a full loop is held back until the loop moves") {
        val (f, vehicles) = squareWithThree()
        val v4 = f.client("v4")
        f.scheduler.allocateNow(v4, setOf("E"))
        f.scheduler.claim(v4, listOf(setOf("E-D", "D"), setOf("D-A", "A")))

        f.allocate(v4, "E-D", "D")

        v4.granted.shouldBeEmpty()
        f.scheduler.grantsHeldBack shouldBe 1
        // v1 leaves the square: now v4 may enter, and will find A free by the time it needs it.
        f.allocate(vehicles[0], "A-B", "B")
        vehicles[0].granted.shouldBeEmpty()
        f.free(vehicles[1], "B")
        vehicles[0].granted shouldContainExactly listOf(setOf("A-B", "B"))
        f.free(vehicles[0], "A")
        v4.granted shouldContainExactly listOf(setOf("E-D", "D"))
    }

    test("a new route whose first step the rule would hold back counts as blocked") {
        val (f, _) = squareWithThree()
        val v4 = f.client("v4")
        f.scheduler.allocateNow(v4, setOf("E"))

        // D is free, so v4 would not wait for itself where it stands; but once on D it would need A, and v1, v2 and
        // v3 would wait for it: a reroute onto this route would break no deadlock, the vehicle would only wait at E.
        f.scheduler.claimWouldBeBlocked(v4, listOf(setOf("E-D", "D"), setOf("D-A", "A"))) shouldBe true
        f.scheduler.claimIsBlocked(v4) shouldBe false
    }

    test("vehicles rotating through a loop with one free point are never held back") {
        val (f, vehicles) = squareWithThree()

        f.allocate(vehicles[2], "C-D", "D")

        vehicles[2].granted shouldContainExactly listOf(setOf("C-D", "D"))
        f.scheduler.grantsHeldBack shouldBe 0
    }

    test("the watchdog sees no deadlock while a vehicle waits behind one that is driving away") {
        val (f, vehicles) = squareWithThree()
        f.allocate(vehicles[2], "C-D", "D")
        f.allocate(vehicles[1], "B-C", "C")

        DeadlockDetector.detect(f.scheduler.waitForGraph()).shouldBeEmpty()
    }

    test("a vehicle inside a single-vehicle block looks past it: entering the loop behind it is held back") {
        // v1 holds the block {B, C} and will need D (v2) after it; v2 needs A; v3 taking A would close the cycle.
        val f =
            SchedulerFixture(
                plant("A-B", "B-C", "C-D", "D-A", "E-A", blocks = listOf(singleVehicleBlock("BC", "B", "B-C", "C"))),
            )
        val (v1, v2, v3) = listOf("v1" to "B", "v2" to "D", "v3" to "E").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        f.scheduler.claim(v1, listOf(setOf("B-C", "C"), setOf("C-D", "D")))
        f.scheduler.claim(v2, listOf(setOf("D-A", "A"), setOf("A-B", "B")))
        f.scheduler.claim(v3, listOf(setOf("E-A", "A"), setOf("A-B", "B")))

        f.allocate(v3, "E-A", "A")

        v3.granted.shouldBeEmpty()
        f.scheduler.grantsHeldBack shouldBe 1
    }

    test("the way out of a two-way stub does not count turning back into it") {
        val model = plant("S-A", "A-S", "A-B", "C-A", "B-C", "B-D")

        val exit = ExitCorridors(model).from("S")

        exit.required shouldBe setOf("S-A", "A", "A-B", "B")
        exit.options shouldContainExactly listOf(setOf("B-C", "C"), setOf("B-D", "D"))
    }

    test("a stop for an operation on a two-way stretch ends the look-ahead with the way out of the stop") {
        // A two-way track A - B - C with a station stub S at B; v2 stands idle at C.
        val model = plant("A-B", "B-A", "B-C", "C-B", "B-S", "S-B")
            .let { it.copy(locations = listOf(Location("L", "station", links = listOf(Link("S"))))) }
        val f = SchedulerFixture(model)
        val (v1, v2) = listOf("v1" to "A", "v2" to "C").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        f.scheduler.claim(v1, listOf(setOf("A-B", "B"), setOf("B-S", "S", "L"), setOf("S-B", "B"), setOf("B-C", "C")))

        // At S, v1 stands aside with a way out over B to A: v2 at C needs nothing v1 keeps from it.
        f.allocate(v1, "A-B", "B")

        v1.granted shouldContainExactly listOf(setOf("A-B", "B"))
        f.scheduler.grantsHeldBack shouldBe 0
        v2.granted.shouldBeEmpty()
    }

    test("a vehicle bound into a dead-end stub over a one-way lane counts the stub's occupant before the lane") {
        // Z -> A -> M one-way, the station stub S at M (two-way), M -> N -> A and N -> X one-way. v2 stands in S and
        // will leave over M and N, where v3 stands and waits for A; v1 at Z is bound for S. On A, v1 would ask for M
        // and wait there for S: a cycle through v2 and v3 one step later, which the one-way step to M hid.
        val model = plant("Z-A", "A-M", "M-S", "S-M", "M-N", "N-A", "N-X")
            .let { it.copy(locations = listOf(Location("L", "station", links = listOf(Link("S"))))) }
        val f = SchedulerFixture(model)
        val (v1, _, v3) = listOf("v1" to "Z", "v2" to "S", "v3" to "N").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        f.scheduler.claim(v1, listOf(setOf("Z-A", "A"), setOf("A-M", "M"), setOf("M-S", "S", "L")))
        f.scheduler.claim(v3, listOf(setOf("N-A", "A")))

        f.allocate(v1, "Z-A", "A")

        v1.granted.shouldBeEmpty()
        f.allocate(v3, "N-A", "A")
        v3.granted shouldContainExactly listOf(setOf("N-A", "A"))
    }

    test("a grant held back while one way on is still free is no deadlock for the watchdog") {
        // The loop P -> Q -> R -> S -> P with station stubs T (at R) and U (at S) and a way on S -> X. v1 stands in T
        // and will leave over R; v2 may not take R (it would wait at R for T); v3 drives from S to P and waits for Q.
        val model = plant("P-Q", "Q-R", "R-S", "S-P", "R-T", "T-R", "S-U", "U-S", "S-X")
            .let {
                it.copy(
                    locations = listOf("L1" to "T", "L2" to "U").map { (name, point) ->
                        Location(name, "station", links = listOf(Link(point)))
                    },
                )
            }
        val f = SchedulerFixture(model)
        val (v1, v2, v3) = listOf("v1" to "T", "v2" to "Q", "v3" to "S").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        f.scheduler.claim(v1, listOf(setOf("T-R", "R"), setOf("R-S", "S"), setOf("S-U", "U", "L2")))
        f.scheduler.claim(v2, listOf(setOf("Q-R", "R"), setOf("R-T", "T", "L1")))
        f.scheduler.claim(v3, listOf(setOf("S-P", "P"), setOf("P-Q", "Q")))
        f.allocate(v3, "S-P", "P")
        f.allocate(v3, "P-Q", "Q")
        f.allocate(v2, "Q-R", "R")
        v2.granted.shouldBeEmpty()

        f.clock.advance(3_000)

        // After T, v2 would need the way out of T: over R and S, then any one of P (v3), U or X; U and X are free.
        DeadlockDetector.detect(f.scheduler.waitForGraph()).shouldBeEmpty()
    }
    test("an operation where the vehicle stands: its fresh claim waits for the first move after the operation") {
        // v1 stands at A beside station L and has a way out over F (B -> F) or on around the square; v2, v3 and v4
        // stand on B, C and D and each wants the next corner, so v4 waits for A.
        val model = plant("A-B", "B-C", "C-D", "D-A", "A-F", "F-B")
            .let { it.copy(locations = listOf(Location("L", "station", links = listOf(Link("A"))))) }
        val f = SchedulerFixture(model)
        val (v1, v2, v3, v4) = listOf("v1" to "A", "v2" to "B", "v3" to "C", "v4" to "D").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        f.scheduler.claim(v2, listOf(setOf("B-C", "C")))
        f.scheduler.claim(v3, listOf(setOf("C-D", "D")))
        f.scheduler.claim(v4, listOf(setOf("D-A", "A")))
        f.scheduler.claimIsBlocked(v1) shouldBe false

        // Its order: an operation at L, where it stands, then on to B, which closes the cycle.
        f.scheduler.claim(v1, listOf(setOf("A", "L"), setOf("A-B", "B")))
        f.scheduler.claimIsBlocked(v1) shouldBe true

        // Routed on over F instead, it waits for nobody; asking first leaves the claim as it is.
        val overF = listOf(setOf("A", "L"), setOf("A-F", "F"), setOf("F-B", "B"))
        f.scheduler.claimWouldBeBlocked(v1, overF) shouldBe false
        f.scheduler.claimIsBlocked(v1) shouldBe true
        f.scheduler.claim(v1, overF)
        f.scheduler.claimIsBlocked(v1) shouldBe false
        f.scheduler.claimWouldBeBlocked(v1, listOf(setOf("A", "L"), setOf("A-B", "B"))) shouldBe true
        f.scheduler.claimIsBlocked(v1) shouldBe false
        f.allocate(v1, "A", "L")
        v1.granted shouldContainExactly listOf(setOf("A", "L"))
    }

    test("a grant the vehicle refused does not hide what it still holds from the watchdog") {
        // v1 at A was granted the way into its park bay P and refused it (it got an order instead); v1 and v2 now
        // face each other on A - B. What v1 holds is A, and it keeps A until it moves: the watchdog must see the cycle.
        val f = SchedulerFixture(plant("A-B", "B-A", "A-P"))
        val (v1, v2) = listOf("v1" to "A", "v2" to "B").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        v1.accepts = false
        f.allocate(v1, "A-P", "P")
        v1.accepts = true

        f.allocate(v1, "A-B", "B")
        f.allocate(v2, "B-A", "A")

        DeadlockDetector.detect(f.scheduler.waitForGraph()).map { it.vehicles.toSet() } shouldContainExactly
            listOf(setOf("v1", "v2"))
    }

    test("a grant that leaves two vehicles waiting only for each other is held back, though neither waits for it") {
        // A two-way track P7 - P8 - P9 - P10 - P11 with junctions at P8 and P10 (a way round over X and Y) and a
        // station bay K at P9 (the warehouse's cross aisle). v1 at P9 will operate in K and leave west over P8; v9 at
        // P10 heads west into K; v13 at P7 heads east along the track.
        val model = plant(
            "P7-P8", "P8-P7", "P8-P9", "P9-P8", "P9-P10", "P10-P9", "P10-P11", "P11-P10", "P9-K", "K-P9",
            "P8-X", "X-P8", "X-Y", "Y-X", "Y-P10", "P10-Y",
        ).let { it.copy(locations = listOf(Location("L", "station", links = listOf(Link("K"))))) }
        val f = SchedulerFixture(model)
        val (v1, v9, v13) = listOf("v1" to "P9", "v9" to "P10", "v13" to "P7").map { (name, point) ->
            f.client(name).also { f.scheduler.allocateNow(it, setOf(point)) }
        }
        f.scheduler.claim(
            v1,
            listOf(setOf("P9-K", "K", "L"), setOf("K-P9", "P9"), setOf("P9-P8", "P8"), setOf("P8-P7", "P7")),
        )
        f.scheduler.claim(v9, listOf(setOf("P10-P9", "P9"), setOf("P9-K", "K")))
        f.scheduler.claim(v13, listOf(setOf("P7-P8", "P8"), setOf("P8-P9", "P9"), setOf("P9-P10", "P10")))

        // In K, v1 may leave by P8 or by P10. With v13 on P8, v1 needs v9 to move and v9 needs v1 to: both wait, and
        // v13 would wait for v1 at P8 for good.
        f.allocate(v13, "P7-P8", "P8")

        v13.granted.shouldBeEmpty()
        f.scheduler.grantsHeldBack shouldBe 1
        // v1 goes into K and comes out west; once it has passed P8, v13 may follow the track.
        f.allocate(v1, "P9-K", "K", "L")
        v1.granted shouldContainExactly listOf(setOf("P9-K", "K", "L"))
    }

    context("two directed squares that share their one free corner X (the grids' dead hole)") {
        // Square A: X -> A1 -> A2 -> A3 -> X; square B: X -> B1 -> B2 -> B3 -> X; a way in E -> B2. a1, a2, a3 stand
        // on A and b1, b3 on B, each bound one step on; a3 and b3 will cross over X into the other square. x0 holds X
        // and B2 (a long vehicle on its way out), so n's, a3's and b3's requests wait, in that order, until it leaves.
        val model = plant("X-A1", "A1-A2", "A2-A3", "A3-X", "X-B1", "B1-B2", "B2-B3", "B3-X", "E-B2")

        fun squares(): Pair<SchedulerFixture, Map<String, RecordingClient>> {
            val f = SchedulerFixture(model)
            val clients = f.place("a1@A1 a2@A2 a3@A3 b1@B1 b3@B3 n@E x0@X+B2")
            fun claim(name: String, vararg steps: String) = f.claimSteps(clients.getValue(name), *steps)
            claim("a1", "A1-A2:A2")
            claim("a2", "A2-A3:A3")
            claim("a3", "A3-X:X", "X-B1:B1")
            claim("b1", "B1-B2:B2")
            claim("b3", "B3-X:X", "X-A1:A1")
            claim("n", "E-B2:B2", "B2-B3:B3")
            return f to clients
        }

        // n, a3, b3 and (if [b1Asks]) b1 ask in this order, then x0 leaves.
        fun SchedulerFixture.askAndClear(v: Map<String, RecordingClient>, b1Asks: Boolean) {
            allocate(v.getValue("n"), "E-B2", "B2")
            allocate(v.getValue("a3"), "A3-X", "X")
            allocate(v.getValue("b3"), "B3-X", "X")
            if (b1Asks) allocate(v.getValue("b1"), "B1-B2", "B2")
            free(v.getValue("x0"), "X", "B2")
        }

        test("a vehicle driving into the last free point but one is held back while the corner can still be taken") {
            val (f, v) = squares()

            // With n on B2 whoever took X would wait, around one square or the other, for itself; a3 can take X.
            f.askAndClear(v, b1Asks = true)

            v.getValue("n").granted.shouldBeEmpty()
            f.scheduler.deadHolesAvoided shouldBeGreaterThan 0
            v.getValue("a3").granted shouldContainExactly listOf(setOf("A3-X", "X"))
            v.getValue("b1").granted shouldContainExactly listOf(setOf("B1-B2", "B2"))
            // a3 drives on into B as B moves.
            f.free(v.getValue("a3"), "A3")
            f.allocate(v.getValue("a3"), "X-B1", "B1")
            f.free(v.getValue("b1"), "B1")
            v.getValue("a3").granted.last() shouldBe setOf("X-B1", "B1")
        }

        test("after the patience the local rule alone decides, so a hold for a paused vehicle cannot stop the fleet") {
            val (f, v) = squares()
            f.scheduler.setPaused(v.getValue("a3"), true)

            f.askAndClear(v, b1Asks = false)
            v.getValue("n").granted.shouldBeEmpty()
            f.clock.advance(TrafficTimers.DEAD_HOLE_PATIENCE_MILLIS - 1)
            f.scheduler.retryOverdue()
            f.clock.drain()
            v.getValue("n").granted.shouldBeEmpty()

            f.clock.advance(1)
            f.scheduler.retryOverdue()
            f.clock.drain()

            v.getValue("n").granted shouldContainExactly listOf(setOf("E-B2", "B2"))
        }

        test("without a vehicle coming in the squares rotate: nothing is held back for a dead hole") {
            val (f, v) = squares()

            f.free(v.getValue("x0"), "X", "B2")
            f.allocate(v.getValue("a3"), "A3-X", "X")
            f.allocate(v.getValue("b1"), "B1-B2", "B2")

            v.getValue("a3").granted shouldContainExactly listOf(setOf("A3-X", "X"))
            v.getValue("b1").granted shouldContainExactly listOf(setOf("B1-B2", "B2"))
            f.scheduler.deadHolesAvoided shouldBe 0
        }
    }

    context("two directed squares that share a corner X held by the vehicle that would free it (a hole two moves on)") {
        // Square A: X -> A1 -> A2 -> A3 -> X; square B: X -> B1 -> B2 -> B3 -> X; a way in E -> A2 and out A2 -> O.
        // m stands on X bound through A out at O; a3 and b3 wait for X to cross into the other square; b1 and b2 wait
        // behind b3. n asks for A2 from E. x0 holds A1 and A2 (a long vehicle on its way out) and then leaves.
        val model = plant("X-A1", "A1-A2", "A2-A3", "A3-X", "X-B1", "B1-B2", "B2-B3", "B3-X", "E-A2", "A2-O")

        test("a grant is held back whose hole only a vehicle can fill that would free a corner nobody can take then") {
            val f = SchedulerFixture(model)
            val v = f.place("m@X a3@A3 b1@B1 b2@B2 b3@B3 n@E x0@A1+A2")
            fun claim(name: String, vararg steps: String) = f.claimSteps(v.getValue(name), *steps)
            claim("m", "X-A1:A1", "A1-A2:A2", "A2-O:O")
            claim("a3", "A3-X:X", "X-B1:B1")
            claim("b1", "B1-B2:B2")
            claim("b2", "B2-B3:B3")
            claim("b3", "B3-X:X", "X-A1:A1")
            claim("n", "E-A2:A2", "A2-A3:A3")
            f.allocate(v.getValue("n"), "E-A2", "A2")
            f.allocate(v.getValue("m"), "X-A1", "A1")
            f.allocate(v.getValue("a3"), "A3-X", "X")
            f.allocate(v.getValue("b3"), "B3-X", "X")
            f.allocate(v.getValue("b1"), "B1-B2", "B2")
            f.allocate(v.getValue("b2"), "B2-B3", "B3")

            // Were n let in, m's only move (to A1) would free X, and a3 and b3 each would then wait, around one square
            // or the other, for itself: X would stay free for good.
            f.free(v.getValue("x0"), "A1", "A2")

            v.getValue("n").granted.shouldBeEmpty()
            f.scheduler.deadHolesAvoided shouldBeGreaterThan 0
            v.getValue("m").granted shouldContainExactly listOf(setOf("X-A1", "A1"))
            // m drives on through A2 and out; b3 follows it into A (a3 would close square B).
            f.free(v.getValue("m"), "X")
            f.allocate(v.getValue("m"), "A1-A2", "A2")
            v.getValue("m").granted.last() shouldBe setOf("A1-A2", "A2")
            f.free(v.getValue("m"), "X-A1", "A1")
            v.getValue("b3").granted shouldContainExactly listOf(setOf("B3-X", "X"))
            v.getValue("a3").granted.shouldBeEmpty()
        }
    }
})

/** Clients standing where [placement] says: `name@POINT` or `name@POINT+POINT`, separated by spaces. */
private fun SchedulerFixture.place(placement: String): Map<String, RecordingClient> =
    placement.split(" ").associate { entry ->
        val name = entry.substringBefore("@")
        name to client(name).also { scheduler.allocateNow(it, entry.substringAfter("@").split("+").toSet()) }
    }

/** Claims [steps] for [client], each `path:point`. */
private fun SchedulerFixture.claimSteps(client: RecordingClient, vararg steps: String) =
    scheduler.claim(client, steps.map { setOf(it.substringBefore(":"), it.substringAfter(":")) })
