package org.ktcs.e2e.plant

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe

class AllocationLedgerTest : FunSpec({
    test("a resource freed by one vehicle before another takes it is no conflict") {
        val ledger = AllocationLedger()
        ledger.update("V1", setOf("Point-1", "Path-1")).shouldBeEmpty()
        ledger.update("V1", setOf("Path-1")).shouldBeEmpty()
        ledger.update("V2", setOf("Point-1")).shouldBeEmpty()
    }

    test("a resource two vehicles hold at once is reported with both") {
        val ledger = AllocationLedger()
        ledger.update("V2", setOf("Point-1"))
        ledger.update("V1", setOf("Point-1", "Point-2")) shouldBe listOf("Point-1 held by [V1, V2]")
    }
})
