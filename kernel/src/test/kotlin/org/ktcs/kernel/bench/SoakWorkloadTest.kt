package org.ktcs.kernel.bench

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import java.io.PrintStream
import java.nio.file.Path

/** The soak compresses plant time by the loopback time factor, and its sweep keeps orders for plant hours. */
class SoakWorkloadTest : FunSpec({
    test("24 plant hours in 40 minutes run at time factor 36, final orders kept one plant hour (100 s)") {
        val soak = SoakWorkload(
            BenchOptions(workload = Workload.SOAK, soakHours = 24.0, soakMinutes = 40.0, keepHours = 1.0),
            Figures(),
            PrintStream(java.io.OutputStream.nullOutputStream()),
        )

        soak.timeFactor shouldBe 36.0
        soak.settings(Path.of("/tmp/soak")) shouldContainAll listOf(
            "kernel.dataDirectory=/tmp/soak",
            "persistence.durability=COMMIT",
            "orderpool.sweepAge=100000",
            "orderpool.sweepInterval=16666",
        )
    }
})
