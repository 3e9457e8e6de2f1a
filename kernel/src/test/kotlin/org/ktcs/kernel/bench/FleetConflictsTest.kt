package org.ktcs.kernel.bench

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.kernel.bench.FleetConflicts.Standing

class FleetConflictsTest : FunSpec({
    test("a resource held by two vehicles counts once per pair and resource, however often it is seen") {
        val fleet = FleetConflicts()
        fleet.snapshot(listOf(Standing("v1", setOf("A", "A-B"), "A"), Standing("v2", setOf("C"), "C")))
        fleet.doubleAllocations() shouldBe 0

        fleet.vehicle(Standing("v2", setOf("C", "C-A", "A"), "C"))
        fleet.vehicle(Standing("v1", setOf("A", "A-B"), "A"))

        fleet.doubleAllocations() shouldBe 1
        fleet.sharedPositions() shouldBe 0
    }

    test("a vehicle that gave a resource up no longer counts as its holder") {
        val fleet = FleetConflicts()
        fleet.snapshot(listOf(Standing("v1", setOf("A", "A-B", "B"), "B"), Standing("v2", setOf("C"), "C")))
        fleet.vehicle(Standing("v1", setOf("B"), "B"))

        fleet.vehicle(Standing("v2", setOf("C", "C-A", "A"), "A"))

        fleet.doubleAllocations() shouldBe 0
    }

    test("two vehicles on one point count, and a vehicle that left a point no longer stands there") {
        val fleet = FleetConflicts()
        fleet.snapshot(listOf(Standing("v1", emptySet(), "A"), Standing("v2", emptySet(), "B")))
        fleet.vehicle(Standing("v1", emptySet(), "C"))
        fleet.vehicle(Standing("v2", emptySet(), "A"))
        fleet.sharedPositions() shouldBe 0

        fleet.vehicle(Standing("v2", emptySet(), "C"))

        fleet.sharedPositions() shouldBe 1
    }

    test("a snapshot's vehicles are checked against each other") {
        val fleet = FleetConflicts()

        fleet.snapshot(listOf(Standing("v1", setOf("A"), "A"), Standing("v2", setOf("A"), "A")))

        fleet.doubleAllocations() shouldBe 1
        fleet.sharedPositions() shouldBe 1
    }
})
