package org.ktcs.kernel.scheduling

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.PointType

/**
 * The park test of deadlock avoidance (developer's guide, section 12): every vehicle must be able to get off the
 * lanes into a park point of its own.
 */
class ParkSafetyTest : FunSpec({
    // The one-way loop a -> b -> c -> d -> a with the park bay c -> P -> d beside it; Q1 to Q3 are park points with a
    // way onto the loop only (nobody can drive to them); z is a dead end off d, from which no park point can be reached.
    val loop =
        parks(
            plant("a-b", "b-c", "c-d", "d-a", "c-P", "P-d", "Q1-a", "Q2-a", "Q3-a", "e-c", "d-z"),
            "P",
            "Q1",
            "Q2",
            "Q3",
        )

    fun ParkSafety.standing(name: String, front: String, vararg held: String) =
        ParkSafety.Standing(name, pointIndex(front), (listOf(front) + held).map(::pointIndex).toIntArray())

    test("a full loop whose vehicles can leave one by one through a free park bay is safe") {
        val safety = ParkSafety(loop)

        safety.isSafe(listOf("a", "b", "c", "d").map { safety.standing("v$it", it) }) shouldBe true
    }

    test("a full loop whose only way to a park point is covered by one of its own vehicles is not safe") {
        val safety = ParkSafety(loop)
        val others = listOf("a", "b", "c").map { safety.standing("v$it", it) }

        // vd has driven out of the bay onto d and still covers P: vc can reach neither d nor P, nobody can move off.
        safety.isSafe(others + safety.standing("vd", "d", "P")) shouldBe false
        safety.isSafe(others + safety.standing("vd", "d")) shouldBe true
    }

    test("a vehicle on a park point, or where no park point can be reached at all, is off the lanes at once") {
        val safety = ParkSafety(loop)
        val full = listOf("a", "b", "c", "d").map { safety.standing("v$it", it) }

        // vP leaves the bay free for vc as it drives on; vz stands where the test has nothing to say.
        safety.isSafe(full + safety.standing("vP", "P")) shouldBe true
        safety.isSafe(listOf(safety.standing("vz", "z"))) shouldBe true
    }

    test("a vehicle behind another gets out once the one in front has gone") {
        // The corridor a -> b -> c -> P: vb must go first, va then reaches P too.
        val safety = ParkSafety(parks(plant("a-b", "b-c", "c-P"), "P"))

        safety.isSafe(listOf(safety.standing("vb", "b"), safety.standing("va", "a"))) shouldBe true
        safety.isSafe(listOf(safety.standing("va", "a"), safety.standing("vb", "b"))) shouldBe true
    }

    test("a vehicle held back can retreat to the nearest free park point it reaches over free points") {
        val safety = ParkSafety(loop)
        val va = safety.standing("va", "a")

        safety.retreatPoint(listOf(va), va) shouldBe "P"
        safety.retreatPoint(listOf(va, safety.standing("vb", "b")), va) shouldBe null
        safety.retreatPoint(listOf(va), va) { it == "P" } shouldBe null
    }

    test("a grant is refused while it would leave the vehicles unable to park, and allowed once it would not") {
        // va on a, vb on b, vd has driven out of the bay onto d and still covers P; ve asks to enter the loop at c.
        val holdings = mutableMapOf("va" to setOf("a"), "vb" to setOf("b"), "vd" to setOf("P", "P-d", "d"))
        val fronts = mapOf("va" to "a", "vb" to "b", "vd" to "d")
        val guard = ParkGuard(ParkSafety(loop), { holdings.keys }, { holdings.getValue(it) }, fronts::get) { false }

        guard.mayGrant("ve", "c", setOf("e-c", "c")) shouldBe false
        guard.heldBack shouldBe 1
        holdings["vd"] = setOf("d")
        guard.changed("vd")
        guard.mayGrant("ve", "c", setOf("e-c", "c")) shouldBe true
    }

    test("with more vehicles than park points the test is off") {
        val holdings = (1..5).associate { "v$it" to setOf("a") }
        val guard = ParkGuard(ParkSafety(loop), { holdings.keys }, { holdings.getValue(it) }, { "a" }) { false }

        guard.mayGrant("v6", "b", setOf("a-b", "b")) shouldBe true
    }
})

/** [model] with [names] as park points. */
private fun parks(model: PlantModel, vararg names: String): PlantModel =
    model.copy(points = model.points.map { if (it.name in names) it.copy(type = PointType.PARK_POSITION) else it })
