package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PointType

/**
 * The park test is a preference, not a wall: a grant it holds back is left to the local rule alone after three seconds
 * of vehicle time (`TrafficTimers.PARK_TEST_PATIENCE_MILLIS`), not before.
 */
class ParkTestPatienceTest : FunSpec({
    // The one-way loop a -> b -> c -> d -> a with the park bay c -> P -> d beside it, a dead end d -> z, and park
    // points Q1 to Q3 with a way onto the loop only.
    val loop = plant("a-b", "b-c", "c-d", "d-a", "c-P", "P-d", "Q1-a", "Q2-a", "Q3-a", "d-z").let { model ->
        val parks = setOf("P", "Q1", "Q2", "Q3")
        model.copy(points = model.points.map { if (it.name in parks) it.copy(type = PointType.PARK_POSITION) else it })
    }

    // va, vb and vc stand on a, b and c; vd stands in the bay and asks for d, its length still covering the bay once
    // there. Then vc can reach neither d nor P: the park test refuses. The local rule has nothing against it: vd's way
    // out of d is a (va) or the free dead end z.
    fun refusedGrant(): Pair<SchedulerFixture, RecordingClient> {
        val f = SchedulerFixture(loop)
        listOf("va" to "a", "vb" to "b", "vc" to "c").forEach { (name, point) ->
            f.scheduler.allocateNow(f.client(name), setOf(point))
        }
        val vd = object : RecordingClient("vd") {
            override fun heldAfter(resources: Set<String>): Set<String> = setOf("P")
        }
        f.scheduler.allocateNow(vd, setOf("P"))
        f.allocate(vd, "P-d", "d")
        return f to vd
    }

    test("a grant the park test refuses waits while the patience lasts") {
        val (f, vd) = refusedGrant()
        vd.granted.shouldBeEmpty()
        f.scheduler.grantWaitOf("vd").first shouldBe GrantWait.PARK_TEST

        f.clock.advance(2_999)
        f.scheduler.retryOverdue()
        f.clock.drain()

        vd.granted.shouldBeEmpty()
        f.scheduler.grantsAfterPatience shouldBe 0
    }

    test("after three seconds of vehicle time the local rule alone decides the grant") {
        val (f, vd) = refusedGrant()

        f.clock.advance(3_000)
        f.scheduler.retryOverdue()
        f.clock.drain()

        vd.granted shouldContainExactly listOf(setOf("P-d", "d"))
        f.scheduler.grantsAfterPatience shouldBe 1
    }
})
