package org.ktcs.kernel.vehicles

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

class HeldResourcesTest : FunSpec({
    val lengths = mapOf("A --- B" to 600L, "B --- C" to 600L, "C --- D" to 2000L)
    fun cover(set: Set<String>) = set.sumOf { lengths[it] ?: 0L }

    fun driving() = HeldResources().apply {
        reset(setOf("A"))
        add(setOf("A --- B", "B"))
        add(setOf("B --- C", "C"))
        add(setOf("C --- D", "D"))
    }

    test("ignoring the vehicle's length, everything behind its point is given back") {
        val held = driving()
        held.passed(setOf("A --- B", "B"), "B") shouldBe setOf("A", "A --- B")
        held.asList() shouldBe listOf(setOf("B"), setOf("B --- C", "C"), setOf("C --- D", "D"))
    }

    test("respecting a 1000 mm vehicle, it keeps the paths behind it that its length still covers") {
        val held = driving()
        held.passed(setOf("A --- B", "B"), "B", ::cover, 1000) shouldBe setOf("A")
        held.passed(setOf("B --- C", "C"), "C", ::cover, 1000) shouldBe emptySet()
        held.asList() shouldBe listOf(setOf("C"), setOf("A --- B", "B"), setOf("B --- C", "C"), setOf("C --- D", "D"))
        held.passed(setOf("C --- D", "D"), "D", ::cover, 1000) shouldBe setOf("A --- B", "B", "B --- C", "C")
        held.asList() shouldBe listOf(setOf("D"), setOf("C --- D", "D"))
    }

    test("two steps ahead, a vehicle longer than the second step still covers the first one") {
        val held = HeldResources().apply { reset(setOf("A")) }
        val steps = listOf(setOf("A --- B", "B"), setOf("B --- C", "C"))
        held.keptAfter(steps, ::cover, 1000) shouldBe setOf("A --- B", "B")
        held.keptAfter(steps, ::cover, 500) shouldBe emptySet()
        held.keptAfter(steps, ::cover, 0) shouldBe emptySet()
    }
})
