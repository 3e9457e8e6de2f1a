package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.maps.shouldBeEmpty
import io.kotest.matchers.shouldBe

// A corridor X-Y-Z, entered eastward from W or V (both marked "east") and westward from E (marked by its name).
private val corridor = plant(
    "W-X", "V-X", "X-Y", "Y-Z", "Z-Y", "Y-X", "E-Z",
    blocks = listOf(sameDirectionBlock("Corridor", "X", "Y", "Z", "X-Y", "Y-Z", "Z-Y", "Y-X")),
    entryDirections = mapOf("W-X" to "east", "V-X" to "east"),
)

class SameDirectionBlockTest : FunSpec({
    test("vehicles entering the same way share the block") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "W-X", "X")
        f.allocate(v1, "X-Y", "Y")
        f.free(v1, "W-X", "X")

        f.allocate(v2, "V-X", "X")

        v2.granted shouldContainExactly listOf(setOf("V-X", "X"))
        f.scheduler.blockDirections() shouldBe mapOf("Corridor" to "east")
    }

    test("a vehicle entering the other way waits until the block is empty") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "W-X", "X")

        f.allocate(v2, "E-Z", "Z")
        v2.granted.shouldBeEmpty()

        f.free(v1, "W-X", "X")
        v2.granted shouldContainExactly listOf(setOf("E-Z", "Z"))
        f.scheduler.blockDirections() shouldBe mapOf("Corridor" to "E-Z")
    }

    test("a request without an entering path continues the direction of a vehicle already inside") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "W-X", "X")
        f.allocate(v1, "X-Y", "Y")
        f.free(v1, "W-X", "X")
        f.allocate(v2, "V-X", "X")

        f.allocate(v1, "Y-Z", "Z")

        v1.granted.last() shouldBe setOf("Y-Z", "Z")
    }

    test("a vehicle outside may not get a member without an entering path while others are inside") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "W-X", "X")

        f.allocate(v2, "Z")

        v2.granted.shouldBeEmpty()
    }

    test("a vehicle placed inside without a direction keeps everybody else out") {
        val f = SchedulerFixture(corridor)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.scheduler.allocateNow(v1, setOf("Y"))

        f.allocate(v2, "W-X", "X")

        v2.granted.shouldBeEmpty()
        f.scheduler.blockDirections().shouldBeEmpty()
    }

    test("a vehicle placed inside sets the direction when it enters, letting others follow it") {
        val model = plant(
            "W-X",
            "U-Y",
            "X-Y",
            "Y-Z",
            blocks = listOf(sameDirectionBlock("Corridor", "X", "Y", "Z", "X-Y", "Y-Z")),
            entryDirections = mapOf("W-X" to "east", "U-Y" to "east"),
        )
        val f = SchedulerFixture(model)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.scheduler.allocateNow(v1, setOf("Z"))
        f.allocate(v2, "W-X", "X")

        f.allocate(v1, "U-Y", "Y")

        v2.granted shouldContainExactly listOf(setOf("W-X", "X"))
    }

    test("the direction is forgotten once the block is empty") {
        val f = SchedulerFixture(corridor)
        val v1 = f.client("v1")
        f.allocate(v1, "W-X", "X")

        f.free(v1, "W-X", "X")

        f.scheduler.blockDirections().shouldBeEmpty()
    }
})
