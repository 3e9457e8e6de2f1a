package org.ktcs.kernel.bench

import com.sun.net.httpserver.HttpServer
import java.net.InetSocketAddress

/** Runs [test] with a bench client of a stand-in kTCS whose `GET /v1/transportOrders` answers [status] and [body]. */
internal fun servingOrderList(status: Int, body: ByteArray, test: (BenchClient) -> Unit) {
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
