package org.ktcs.kernel.validation

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

class BlockChecksTest : FunSpec({
    test("a member naming no point, path or location is an error") {
        val model = minimalPlant().mapBlocks { it.copy(members = setOf("A", "Ghost")) }

        model.problems() shouldBe
            listOf(expectedError("block 'Block-01'", "member 'Ghost' names no point, path or location"))
    }

    test("a member naming a vehicle is an error") {
        val model = minimalPlant().mapBlocks { it.copy(members = setOf("Vehicle-01")) }

        model.problems() shouldBe
            listOf(expectedError("block 'Block-01'", "member 'Vehicle-01' names no point, path or location"))
    }

    test("a block without members is only a warning") {
        val model = minimalPlant().mapBlocks { it.copy(members = emptySet()) }

        model.problems() shouldBe listOf(expectedWarning("block 'Block-01'", "has no members"))
        model.errors() shouldBe emptyList()
    }
})
