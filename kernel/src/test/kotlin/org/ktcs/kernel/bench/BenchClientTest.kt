package org.ktcs.kernel.bench

import com.sun.net.httpserver.HttpServer
import io.kotest.assertions.throwables.shouldThrow
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import java.net.InetSocketAddress

/** The bench's JDK client: a list of several megabytes is read and counted, not kept. */
class BenchClientTest : FunSpec({
    fun serving(status: Int, body: ByteArray, test: (BenchClient) -> Unit) {
        val server = HttpServer.create(InetSocketAddress("127.0.0.1", 0), 0)
        server.createContext("/v1/transportOrders") { exchange ->
            exchange.sendResponseHeaders(status, body.size.toLong())
            exchange.responseBody.use { it.write(body) }
        }
        server.start()
        try {
            test(BenchClient("http://127.0.0.1:${server.address.port}/v1"))
        } finally {
            server.stop(0)
        }
    }

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
