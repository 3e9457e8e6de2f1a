package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PointType
import org.ktcs.api.scheduling.Retreat

/**
 * A vehicle held back retreats into a dead-end bay only after [DefaultScheduler]'s longer wait: driving in and back
 * out through the aisle pays only for a vehicle stuck for longer than a queue moving along.
 */
class DeadEndRetreatTest : FunSpec({
    test("a stub's end is a dead end; a detour bay and a point on a lane are not") {
        val exits = ExitCorridors(plant("A-B", "B-A", "B-K", "K-B", "B-C", "C-D", "C-P", "P-D"))

        exits.isDeadEnd("K") shouldBe true
        exits.isDeadEnd("P") shouldBe false
        exits.isDeadEnd("C") shouldBe false
        exits.isDeadEnd("A") shouldBe true
    }

    test("a vehicle held back head-on retreats into the dead-end bay beside it after six seconds, not after two") {
        // The two-way track A - B - C with dead-end park bays K (at B) and L (at C). v1 at A and v2 at C are headed
        // for each other's points: v1's step onto B is held back for good.
        val (f, v1, _) = headOn()
        v1.granted.shouldBeEmpty()

        f.clock.advance(2_000)
        f.scheduler.retreats { true }.toList().shouldBeEmpty()

        f.clock.advance(4_000)
        f.scheduler.retreats { true }.toList() shouldBe listOf(Retreat("v1", "K"))
    }

    test("two vehicles head-on whose next steps the local rule holds back for each other are found as such") {
        val (f, _, v2) = headOn()
        f.scheduler.refusedMutually("v1") shouldBe emptySet()

        f.allocate(v2, "C-B", "B")
        v2.granted.shouldBeEmpty()
        f.scheduler.refusedMutually("v1") shouldBe setOf("v2")
        f.scheduler.refusedMutually("v2") shouldBe setOf("v1")
    }

    test("a client that does not say how long it is counts, two steps ahead, the first step as still covered") {
        val client = RecordingClient("v")

        client.heldAfter(listOf(setOf("A-B", "B"), setOf("B-K", "K"))) shouldBe setOf("A-B", "B")
    }

    test("a vehicle retreats into no bay where another vehicle's order ends: the two would meet at its mouth") {
        // As above, and v3 at A's far side is sent to park in K: v1 is sent to L instead, and to K once v3's park order
        // ends elsewhere.
        val f = SchedulerFixture(withBays("A-B", "B-A", "B-C", "C-B", "B-K", "K-B", "C-L", "L-C", "X-A", "A-X"))
        val v1 = f.client("v1").also { f.scheduler.allocateNow(it, setOf("B")) }
        val v3 = f.client("v3").also { f.scheduler.allocateNow(it, setOf("X")) }
        f.scheduler.claim(v3, listOf(setOf("X-A", "A"), setOf("A-B", "B"), setOf("B-K", "K")))

        f.scheduler.retreatPoint("v1") shouldBe "L"
        f.scheduler.claim(v3, listOf(setOf("X-A", "A")))
        f.scheduler.retreatPoint("v1") shouldBe "K"
    }
})

// The plant of [paths] with its points K and L as park positions.
private fun withBays(vararg paths: String) = plant(*paths).let { model ->
    model.copy(
        points = model.points.map {
            if (it.name in setOf("K", "L")) it.copy(type = PointType.PARK_POSITION) else it
        },
    )
}

// The two-way track A - B - C with dead-end park bays K (at B) and L (at C); v1 at A and v2 at C, each claiming the
// way to the other's point, and v1 asking for B.
private fun headOn(): Triple<SchedulerFixture, RecordingClient, RecordingClient> {
    val f = SchedulerFixture(withBays("A-B", "B-A", "B-C", "C-B", "B-K", "K-B", "C-L", "L-C"))
    val v1 = f.client("v1").also { f.scheduler.allocateNow(it, setOf("A")) }
    val v2 = f.client("v2").also { f.scheduler.allocateNow(it, setOf("C")) }
    f.scheduler.claim(v1, listOf(setOf("A-B", "B"), setOf("B-C", "C")))
    f.scheduler.claim(v2, listOf(setOf("C-B", "B"), setOf("B-A", "A")))
    f.allocate(v1, "A-B", "B")
    return Triple(f, v1, v2)
}
