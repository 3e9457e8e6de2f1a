package org.ktcs.kernel.bench

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe

class ThreadCpuTest : FunSpec({
    test("a pool's threads count as one kind, a thread that started counts from zero, largest kind first") {
        val before = mapOf(1L to ("kernel" to 1.0), 2L to ("DefaultDispatcher-worker-1" to 2.0))
        val after = mapOf(
            1L to ("kernel" to 1.5),
            2L to ("DefaultDispatcher-worker-1" to 3.0),
            3L to ("DefaultDispatcher-worker-12" to 0.25),
            4L to ("idle" to 0.0),
        )

        ThreadCpu.byKind(before, after) shouldContainExactly
            listOf("DefaultDispatcher-worker-#" to 1.25, "kernel" to 0.5)
    }

    test("digits in a name make no kind of their own") {
        ThreadCpu.kind("C2 CompilerThre0") shouldBe "C# CompilerThre#"
    }
})
