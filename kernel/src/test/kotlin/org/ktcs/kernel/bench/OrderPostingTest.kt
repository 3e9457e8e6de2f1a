package org.ktcs.kernel.bench

import com.sun.net.httpserver.HttpServer
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainOnly
import io.kotest.matchers.shouldBe
import java.net.InetSocketAddress
import java.util.Collections

/** Order creation is timed over the POSTs alone: the clients' set-up happens before the clock starts. */
class OrderPostingTest : FunSpec({
    /** Serves [test] a client whose server logs each request as "GET" or "POST" in the returned order of events. */
    fun serving(test: (BenchClient, MutableList<String>) -> Unit) {
        val events = Collections.synchronizedList(ArrayList<String>())
        val server = HttpServer.create(InetSocketAddress("127.0.0.1", 0), 0)
        server.createContext("/v1/transportOrders/") { exchange ->
            exchange.requestBody.use { it.readAllBytes() }
            events += exchange.requestMethod
            val status = if (exchange.requestMethod == "POST") 200 else 404
            val body = "{}".toByteArray()
            exchange.sendResponseHeaders(status, body.size.toLong())
            exchange.responseBody.use { it.write(body) }
        }
        server.start()
        try {
            test(BenchClient("http://127.0.0.1:${server.address.port}/v1"), events)
        } finally {
            server.stop(0)
        }
    }

    val orders = List(40) { BenchOrder("order-$it", "A", "B") }

    listOf(ClientKind.JDK, ClientKind.RAW).forEach { kind ->
        listOf(1, 8).forEach { clients ->
            test("$clients $kind clients post every order between the clock's start and stop, set-up before") {
                serving { client, events ->
                    val result = OrderPosting.post(client, orders, clients, kind, {
                        events += "start"
                    }, { events += "stop" })

                    result.count shouldBe orders.size
                    result.latenciesMillis.size shouldBe orders.size
                    val start = events.indexOf("start")
                    events.take(start).filter { it != "GET" } shouldBe emptyList()
                    events.subList(start + 1, events.size - 1) shouldContainOnly listOf("POST")
                    events.count { it == "POST" } shouldBe orders.size
                    events.last() shouldBe "stop"
                }
            }
        }
    }

    test("the JDK client opens its connections before the clock starts, with a GET of an unknown order") {
        serving { client, events ->
            OrderPosting.post(client, orders, 8, ClientKind.JDK, { events += "start" }, {})

            events.indexOf("start") shouldBe events.count { it == "GET" }
            events.count { it == "GET" } shouldBe 8
        }
    }
})
