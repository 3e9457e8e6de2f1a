package org.ktcs.adapters.loopback

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.doubles.plusOrMinus
import io.kotest.matchers.doubles.shouldBeGreaterThanOrEqual
import io.kotest.matchers.doubles.shouldBeLessThanOrEqual
import io.kotest.matchers.shouldBe
import io.kotest.property.Arb
import io.kotest.property.arbitrary.boolean
import io.kotest.property.arbitrary.numericDouble
import io.kotest.property.checkAll
import kotlin.math.sqrt

class VelocityProfileTest : FunSpec({
    fun stop(length: Double, v0: Double = 0.0, vMax: Double = 1000.0, a: Double = 500.0, d: Double = 500.0) =
        VelocityProfile.plan(length, v0, vMax, a, d, stopAtEnd = true)

    fun roll(length: Double, v0: Double = 0.0, vMax: Double = 1000.0, a: Double = 500.0, d: Double = 500.0) =
        VelocityProfile.plan(length, v0, vMax, a, d, stopAtEnd = false)

    test("a long path accelerates, cruises and brakes: t = v/a + (L - v²/2a - v²/2d)/v + v/d") {
        // 2 s up (1000 mm), 8000 mm at 1000 mm/s, 2 s down (1000 mm)
        stop(10_000.0).durationSeconds shouldBe (12.0 plusOrMinus 1e-9)
        stop(10_000.0).phases.size shouldBe 3
        stop(10_000.0).endVelocity shouldBe (0.0 plusOrMinus 1e-9)
    }

    test("different acceleration and deceleration give different ramps") {
        // 4 s up (2000 mm), 2 s down (1000 mm), 7000 mm cruising
        stop(10_000.0, a = 250.0).durationSeconds shouldBe (13.0 plusOrMinus 1e-9)
    }

    test("a short path never reaches cruise speed: t = 2·sqrt(L/a) for a = d") {
        val motion = stop(1_000.0)
        motion.durationSeconds shouldBe (2 * sqrt(2.0) plusOrMinus 1e-9)
        motion.phases.first().endVelocity shouldBe (sqrt(500_000.0) plusOrMinus 1e-9)
    }

    test("a vehicle that keeps going does not brake at the end") {
        val motion = roll(10_000.0)
        motion.durationSeconds shouldBe (11.0 plusOrMinus 1e-9)
        motion.endVelocity shouldBe (1000.0 plusOrMinus 1e-9)
    }

    test("a vehicle already moving only brakes") {
        stop(10_000.0, v0 = 1000.0).durationSeconds shouldBe (11.0 plusOrMinus 1e-9)
        roll(10_000.0, v0 = 1000.0).durationSeconds shouldBe (10.0 plusOrMinus 1e-9)
    }

    test("a vehicle faster than the path allows slows down first") {
        // 1 s from 1000 to 500 mm/s (750 mm), 9000 mm at 500 mm/s, 1 s to 0 (250 mm)
        stop(10_000.0, v0 = 1000.0, vMax = 500.0).durationSeconds shouldBe (20.0 plusOrMinus 1e-9)
    }

    test("a vehicle too fast to stop brakes all the way and arrives moving") {
        val motion = stop(500.0, v0 = 1000.0)
        motion.durationSeconds shouldBe ((1000.0 - sqrt(500_000.0)) / 500.0 plusOrMinus 1e-9)
        motion.endVelocity shouldBe (sqrt(500_000.0) plusOrMinus 1e-9)
    }

    test("a short path while rolling only accelerates") {
        val motion = roll(100.0)
        motion.durationSeconds shouldBe (sqrt(2 * 100.0 / 500.0) plusOrMinus 1e-9)
        motion.endVelocity shouldBe (sqrt(2 * 500.0 * 100.0) plusOrMinus 1e-9)
    }

    test("a zero-length path takes no time") {
        stop(0.0).durationSeconds shouldBe 0.0
        stop(0.0).phases shouldBe emptyList()
    }

    test("distance and time along the profile invert each other") {
        val motion = stop(10_000.0)
        motion.distanceAt(1.0) shouldBe (250.0 plusOrMinus 1e-9)
        motion.distanceAt(6.0) shouldBe (5_000.0 plusOrMinus 1e-9)
        motion.distanceAt(99.0) shouldBe (10_000.0 plusOrMinus 1e-9)
        motion.timeAt(5_000.0) shouldBe (6.0 plusOrMinus 1e-9)
        motion.timeAt(10_000.0) shouldBe (12.0 plusOrMinus 1e-9)
    }

    test("rejects impossible arguments") {
        shouldThrow<IllegalArgumentException> { stop(-1.0) }
        shouldThrow<IllegalArgumentException> { stop(10.0, vMax = 0.0) }
        shouldThrow<IllegalArgumentException> { stop(10.0, a = 0.0) }
    }

    fun finite(min: Double, max: Double) = Arb.numericDouble(min, max)

    test("every plan covers the whole path, no faster than its top speed allows") {
        checkAll(
            finite(0.0, 1e6),
            finite(0.0, 2000.0),
            finite(10.0, 2000.0),
            finite(10.0, 1000.0),
            finite(10.0, 1000.0),
            Arb.boolean(),
        ) { length, v0, vMax, a, d, stopAtEnd ->
            val motion = VelocityProfile.plan(length, v0, vMax, a, d, stopAtEnd)
            motion.length shouldBe (length plusOrMinus 1e-6 * (1 + length))
            motion.durationSeconds * maxOf(v0, vMax) shouldBeGreaterThanOrEqual length * (1 - 1e-9) - 1e-9
            motion.phases.forEach { it.endVelocity shouldBeGreaterThanOrEqual -1e-6 }
            motion.phases.forEach { it.endVelocity shouldBeLessThanOrEqual maxOf(v0, vMax) + 1e-6 }
            if (stopAtEnd && v0 * v0 <= 2 * d * length) motion.endVelocity shouldBe (0.0 plusOrMinus 1e-6)
            val t = motion.durationSeconds / 3
            motion.timeAt(motion.distanceAt(t)) shouldBe (t plusOrMinus 1e-6 * (1 + t))
        }
    }
})
