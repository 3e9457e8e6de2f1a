package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.scheduling.SchedulerWaits

class DeadlockDetectorTest : FunSpec({
    test("two vehicles each waiting for what the other holds are a deadlock") {
        val allocations = mapOf("v1" to setOf("A"), "v2" to setOf("B"))
        val pending = mapOf("v1" to listOf(setOf("B")), "v2" to listOf(setOf("A", "C")))

        DeadlockDetector.detect(allocations, pending) shouldContainExactly listOf(
            Deadlock(listOf("v1", "v2"), setOf("B", "A")),
        )
    }

    test("three vehicles waiting in a ring are one deadlock, in waiting order") {
        val allocations = mapOf("v1" to setOf("A"), "v2" to setOf("B"), "v3" to setOf("C"))
        val pending = mapOf("v1" to listOf(setOf("C")), "v2" to listOf(setOf("A")), "v3" to listOf(setOf("B")))

        DeadlockDetector.detect(allocations, pending) shouldContainExactly listOf(
            Deadlock(listOf("v1", "v3", "v2"), setOf("C", "B", "A")),
        )
    }

    test("a chain of waiting vehicles is no deadlock") {
        val allocations = mapOf("v1" to setOf("A"), "v2" to setOf("B"), "v3" to setOf("C"))
        val pending = mapOf("v1" to listOf(setOf("B")), "v2" to listOf(setOf("C")), "v3" to listOf(setOf("D")))

        DeadlockDetector.detect(allocations, pending).shouldBeEmpty()
    }

    test("only the oldest pending request of a vehicle counts") {
        val allocations = mapOf("v1" to setOf("A"), "v2" to setOf("B"))
        val pending = mapOf("v1" to listOf(setOf("C"), setOf("B")), "v2" to listOf(setOf("A")))

        DeadlockDetector.detect(allocations, pending).shouldBeEmpty()
    }

    test("two rings sharing a vehicle are both reported") {
        val allocations = mapOf("v1" to setOf("A"), "v2" to setOf("B"), "v3" to setOf("C"))
        val pending = mapOf("v1" to listOf(setOf("B", "C")), "v2" to listOf(setOf("A")), "v3" to listOf(setOf("A")))

        DeadlockDetector.detect(allocations, pending).map { it.vehicles } shouldContainExactly listOf(
            listOf("v1", "v2"),
            listOf("v1", "v3"),
        )
    }

    test("proposes rerouting the vehicle with the fewest resources to avoid") {
        val allocations = mapOf("v1" to setOf("A", "A2"), "v2" to setOf("B"), "v3" to setOf("C", "C2"))
        val pending = mapOf(
            "v1" to listOf(setOf("C", "C2")),
            "v2" to listOf(setOf("A", "A2")),
            "v3" to listOf(setOf("B", "X")),
        )
        val graph = WaitForGraph(SchedulerWaits.of(allocations, pending))
        val deadlock = DeadlockDetector.detect(graph).single()

        DeadlockDetector.resolve(deadlock, graph) shouldBe DeadlockResolution("v3", setOf("B"))
        DeadlockDetector.resolutions(deadlock, graph).map { it.vehicle } shouldContainExactly listOf("v3", "v1", "v2")
    }

    test("finds a deadlock the scheduler's vehicles ran into") {
        val f = SchedulerFixture()
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "A")
        f.allocate(v2, "B")
        f.allocate(v1, "A-B", "B")
        f.allocate(v2, "A")

        val graph = f.scheduler.waitForGraph()
        val deadlock = DeadlockDetector.detect(graph).single()

        deadlock shouldBe Deadlock(listOf("v1", "v2"), setOf("B", "A"))
        DeadlockDetector.detect(f.scheduler.allocations(), f.scheduler.pendingAllocations()) shouldBe listOf(deadlock)
        DeadlockDetector.resolve(deadlock, graph) shouldBe DeadlockResolution("v1", setOf("B"))
    }

    test("the scheduler's graph shows vehicles kept out of a block by the direction of its users") {
        val model = plant(
            "W-X",
            "X-Y",
            "Y-E",
            "E-Y",
            blocks = listOf(sameDirectionBlock("Corridor", "X", "Y", "X-Y")),
        )
        val f = SchedulerFixture(model)
        val (v1, v2) = f.client("v1") to f.client("v2")
        f.allocate(v1, "W-X", "X")
        f.allocate(v2, "E")
        f.allocate(v2, "E-Y", "Y")
        f.allocate(v1, "X-Y", "Y", "Y-E", "E")

        val deadlock = DeadlockDetector.detect(f.scheduler.waitForGraph()).single()

        deadlock.vehicles shouldContainExactly listOf("v1", "v2")
        deadlock.resources shouldBe setOf("E", "X", "Y", "X-Y")
    }
})
