package org.ktcs.kernel.dispatching

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

class RefusalTest : FunSpec({
    test("one vehicle's refusal names the vehicle") {
        describe(listOf(Refusal("V1", "driver refused: full"))) shouldBe "vehicle V1: driver refused: full"
    }

    test("the same refusal from every vehicle is summarised") {
        val refusals = listOf("V2", "V1").map { Refusal(it, "does not accept type 'X'", "no vehicle accepts type 'X'") }
        describe(refusals) shouldBe "no vehicle accepts type 'X'"
    }

    test("different refusals are listed by vehicle name, the first three only") {
        val refusals = (5 downTo 1).map { Refusal("V$it", "reason $it") }
        describe(refusals) shouldBe
            "vehicle V1: reason 1; vehicle V2: reason 2; vehicle V3: reason 3; and 2 more vehicles"
    }

    test("the deferral log passes a reason on only when it changes, and again after an assignment") {
        val context = FakeDispatchContext(plant())
        val log = DeferralLog(context)

        log.record("T1", "a")
        log.record("T1", "a")
        log.record("T1", "b")
        log.assigned("T1")
        log.record("T1", "b")
        log.record("T2", "c")
        log.retainOnly(setOf("T1"))
        log.record("T2", "c")

        context.deferrals shouldContainExactly
            listOf("T1" to "a", "T1" to "b", "T1" to "b", "T2" to "c", "T2" to "c")
    }
})
