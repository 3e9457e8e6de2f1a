package org.ktcs.kernel.bench

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import java.time.Instant

/** The batch's end by the kernel's clock: the latest finish of the batch's finished orders, nothing else. */
class KernelFinishTimesTest : FunSpec({
    fun serving(body: String?, test: (BenchClient) -> Unit) =
        servingOrderList(if (body == null) 503 else 200, body?.toByteArray() ?: ByteArray(0), test)

    fun order(name: String, state: String, finished: String) =
        """{"name":"$name","state":"$state","finishedTime":"$finished","driveOrders":[]}"""

    test("the latest finish of the batch's FINISHED orders; other batches' and unfinished orders do not count") {
        val list = listOf(
            order("Batch-a-1", "FINISHED", "2026-11-30T10:00:05Z"),
            order("Batch-a-2", "FINISHED", "2026-11-30T10:00:09.250Z"),
            order("Batch-a-3", "FAILED", "2026-11-30T10:00:30Z"),
            order("Batch-b-1", "FINISHED", "2026-11-30T10:01:00Z"),
            order("Batch-a-4", "BEING_PROCESSED", "+1000000000-12-31T23:59:59.999999999Z"),
        ).joinToString(",", "[", "]")
        serving(list) { client ->
            KernelFinishTimes.lastFinished(client, "Batch-a-") shouldBe Instant.parse("2026-11-30T10:00:09.250Z")
        }
    }

    test("no finished order of the batch, or no answer: no figure") {
        serving("[${order("Batch-a-1", "FAILED", "2026-11-30T10:00:05Z")}]") { client ->
            KernelFinishTimes.lastFinished(client, "Batch-a-") shouldBe null
        }
        serving(null) { client -> KernelFinishTimes.lastFinished(client, "Batch-a-") shouldBe null }
    }

    test("an answer that is no list of orders, or a finish that is no instant, fails with what was wrong") {
        serving("""{"name":"not a list"}""") { client ->
            shouldThrow<IllegalStateException> { KernelFinishTimes.lastFinished(client, "Batch-a-") }
                .message shouldStartWith "GET /transportOrders answered no list of orders"
        }
        serving("[${order("Batch-a-1", "FINISHED", "yesterday")}]") { client ->
            shouldThrow<IllegalStateException> { KernelFinishTimes.lastFinished(client, "Batch-a-") }
                .message shouldStartWith "GET /transportOrders answered a finishedTime that is no instant"
        }
        serving("[{\"name\":") { client ->
            shouldThrow<IllegalStateException> { KernelFinishTimes.lastFinished(client, "Batch-a-") }
                .message shouldStartWith "GET /transportOrders answered no list of orders"
        }
    }
})
