package org.ktcs.kernel.core

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

/**
 * The watchdog's memory of stuck states. The pattern from the 30x30 grid: the cycle search shows one knot of
 * vehicles as a 4-vehicle cycle at one check and as a 16-vehicle cycle containing it at the next, and rerouting
 * changes nothing; that is one deadlock, not one per check, and it is not rerouted at every check.
 */
class StuckStatesTest : FunSpec({
    val small = listOf("V1", "V2", "V3", "V4")
    val large = small + listOf("V5", "V6", "V7", "V8")
    val positions = (small + large).associateWith { setOf("P-$it") }.toMutableMap()
    fun held(vehicle: String) = positions.getValue(vehicle)

    test("a knot shown as different cycles at different checks counts once and is retried at growing intervals") {
        val stuck = StuckStates(maxBackOff = 8)
        val attempts = ArrayList<Int>()
        for (check in 1..20) {
            stuck.startCheck(::held) { true }
            val verdict = stuck.observe(if (check % 2 == 1) small else large, ::held)
            verdict.isNew shouldBe (check == 1)
            if (verdict.resolveNow) attempts += check
        }

        stuck.detected shouldBe 1
        attempts shouldContainExactly listOf(1, 2, 4, 8, 16)
    }

    test("two cycles of one knot in the same check: one report, one attempt") {
        val stuck = StuckStates()
        stuck.startCheck(::held) { true }

        stuck.observe(small, ::held) shouldBe StuckStates.Verdict(isNew = true, resolveNow = true)
        stuck.observe(large, ::held) shouldBe StuckStates.Verdict(isNew = false, resolveNow = false)
        stuck.detected shouldBe 1
    }

    test("once a vehicle of the knot moves, the deadlock counts as resolved and a later cycle is a new one") {
        val stuck = StuckStates()
        stuck.startCheck(::held) { true }
        stuck.observe(small, ::held)
        stuck.rerouted(small)

        positions["V2"] = setOf("P-elsewhere")
        stuck.startCheck(::held) { true }

        stuck.resolved shouldBe 1
        stuck.observe(small, ::held) shouldBe StuckStates.Verdict(isNew = true, resolveNow = true)
        stuck.detected shouldBe 2
    }

    test("a knot whose vehicle stops waiting ends without counting as resolved when nobody was rerouted") {
        val stuck = StuckStates()
        stuck.startCheck(::held) { true }
        stuck.observe(small, ::held)

        stuck.startCheck(::held) { it != "V3" }

        stuck.resolved shouldBe 0
        stuck.observe(small, ::held).isNew shouldBe true
    }
})
