package org.ktcs.adapters.vda5050.broker

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.longs.shouldBeGreaterThanOrEqual
import io.kotest.matchers.longs.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.netty.channel.SelectStrategy
import io.netty.util.IntSupplier

private fun timed(block: () -> Int): Pair<Int, Long> {
    val start = System.nanoTime()
    val result = block()
    return result to (System.nanoTime() - start) / 1_000_000
}

/** The builtin broker's event loop pauses after a round of work, unless it has tasks waiting or no pause is set. */
class BatchingSelectTest : FunSpec({
    val three = IntSupplier { 3 }
    val none = IntSupplier { 0 }

    test("with no tasks it pauses, then reads what is ready or waits for the next message") {
        val strategy = BatchingSelect(40).newSelectStrategy()
        val (ready, pause) = timed { strategy.calculateStrategy(three, false) }
        ready shouldBe 3
        pause shouldBeGreaterThanOrEqual 40
        strategy.calculateStrategy(none, false) shouldBe SelectStrategy.SELECT
    }

    test("tasks waiting, or no pause set: no pause") {
        val (withTasks, pause) = timed { BatchingSelect(1000).newSelectStrategy().calculateStrategy(three, true) }
        withTasks shouldBe 3
        pause shouldBeLessThan 500
        val (idle, noPause) = timed { BatchingSelect(0).newSelectStrategy().calculateStrategy(three, false) }
        idle shouldBe SelectStrategy.SELECT
        noPause shouldBeLessThan 500
    }
})
