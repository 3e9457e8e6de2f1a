package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

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
})
