package org.ktcs.kernel.bench

import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe

/** The bench's JDK client: a list of several megabytes is read and counted, not kept. */
class BenchClientTest : FunSpec({
    fun serving(status: Int, body: ByteArray, test: (BenchClient) -> Unit) = servingOrderList(status, body, test)

    test("a GET's body of several megabytes is read to its end and its length counted") {
        val body = ByteArray(5_000_003) { (it % 251).toByte() }
        serving(200, body) { client -> client.getDiscarding("/transportOrders") shouldBe 5_000_003L }
    }

    test("a GET answered with an error fails with the status") {
        serving(500, ByteArray(10)) { client ->
            shouldThrow<IllegalStateException> { client.getDiscarding("/transportOrders") }.message shouldBe
                "GET /transportOrders answered 500"
        }
    }
})
