package org.ktcs.kernel.dispatching

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

class DefaultRecoveryEvaluatorTest : FunSpec({
    test("a vehicle recovers at the sufficient level or at 70 %, whichever is higher") {
        val evaluator = DefaultRecoveryEvaluator()

        evaluator.isRecovered(energyLevel = 69, sufficientlyRecharged = 30, fullyRecharged = 90) shouldBe false
        evaluator.isRecovered(energyLevel = 70, sufficientlyRecharged = 30, fullyRecharged = 90) shouldBe true
        evaluator.isRecovered(energyLevel = 79, sufficientlyRecharged = 80, fullyRecharged = 90) shouldBe false
        evaluator.isRecovered(energyLevel = 80, sufficientlyRecharged = 80, fullyRecharged = 90) shouldBe true
    }

    test("the threshold is configurable and must be a share") {
        DefaultRecoveryEvaluator(threshold = 0.2).isRecovered(30, 30, 90) shouldBe true
        shouldThrow<IllegalArgumentException> { DefaultRecoveryEvaluator(threshold = 1.5) }
    }
})
