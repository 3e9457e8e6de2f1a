package org.ktcs.xmlchannels.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.ints.shouldBeLessThan
import io.kotest.matchers.string.shouldContain
import io.kotest.matchers.string.shouldNotContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.HostClient
import org.ktcs.xmlchannels.sample
import org.ktcs.xmlchannels.status.StatusClientSocket
import org.ktcs.xmlchannels.status.withStatusClients
import org.ktcs.xmlchannels.testSettings
import org.ktcs.xmlchannels.toOrder
import org.ktcs.xmlchannels.withChannels
import java.net.InetAddress
import java.net.Socket
import kotlin.time.Duration.Companion.milliseconds

/**
 * Faults from issue #14 that once silenced a channel: a message XML cannot carry, clients that trickle bytes, and
 * connection floods. Each case ends with the channels still doing their work.
 */
class ChannelFaultsTest : FunSpec({
    val telegram = sample("xml-telegram-two-orders.xml")
    val order = TransportOrderCreation(
        "TOrder-0001",
        listOf(Destination("Storage 01", "Load cargo")),
    ).toOrder("TOrder-0001")

    test("a message XML cannot carry is skipped; the status channel goes on with the next one") {
        val services = FakeKernelServices()
        val next = withStatusClients(services, 1) { _, (client) ->
            services.events.emit(TransportOrderEvent(null, order.copy(name = "Ctl-\u0001x")))
            services.events.emit(TransportOrderEvent(null, order.copy(properties = mapOf("k" to "a\u0000b"))))
            services.events.emit(TransportOrderEvent(null, order))
            client.next()!!
        }

        next shouldContain "orderName=\"TOrder-0001\""
        next shouldNotContain "Ctl-"
    }

    test("a client that sends one byte now and then is closed when its telegram's deadline passes") {
        val services = FakeKernelServices()
        val elapsed = withChannels(services) { channels ->
            withContext(Dispatchers.IO) {
                HostClient.connect(channels.ordersPort).use { socket ->
                    val started = System.nanoTime()
                    // 100 ms between bytes is well within a 300 ms deadline per read, never within it per telegram.
                    for (index in 0 until 40) {
                        val sent = runCatching {
                            socket.getOutputStream().apply {
                                write(telegram[index].code)
                                flush()
                            }
                        }
                        if (sent.isFailure) break
                        Thread.sleep(100)
                    }
                    runCatching { socket.getInputStream().read() }
                    (System.nanoTime() - started) / 1_000_000
                }
            }
        }

        elapsed.toInt() shouldBeLessThan 2_000
        services.created.shouldBeEmpty()
    }

    test("a flood of silent connections on one port is refused clearly and silences neither channel") {
        val services = FakeKernelServices()
        val settings = testSettings().copy(
            ordersMaxConnections = 4,
            statusMaxConnections = 4,
            idleTimeout = 3_000.milliseconds,
        )
        withChannels(services, settings) { channels ->
            val flood = List(12) { HostClient.connect(channels.ordersPort) }
            val statusFlood = List(12) { Socket(InetAddress.getLoopbackAddress(), channels.statusPort) }
            try {
                val refusals = flood.map { answerOf(it) }.filter { it.contains("too many connections") }
                refusals shouldHaveSize 8
                // The silent ones time out; then a real telegram is answered.
                withTimeout(8_000) {
                    var receipt = ""
                    while (!receipt.contains("tcsResponseSet")) receipt = HostClient.send(channels.ordersPort, telegram)
                }
                services.created shouldHaveSize 2
            } finally {
                flood.forEach(Socket::close)
                statusFlood.forEach(Socket::close)
            }
        }
    }

    test("a flood of silent status clients beyond the limit is refused; the clients already connected are served") {
        val services = FakeKernelServices()
        val settings = testSettings().copy(statusMaxConnections = 2)
        withChannels(services, settings) { channels ->
            val clients = List(2) { StatusClientSocket(channels.statusPort) }
            withTimeout(5_000) {
                services.events.subscriptionCount.first { it > 0 }
                channels.statusClients.first { it == 2 }
            }
            val refused = Socket(InetAddress.getLoopbackAddress(), channels.statusPort)
            try {
                answerOf(refused) shouldContain "too many connections"
                services.events.emit(TransportOrderEvent(null, order))
                clients.forEach { it.next()!! shouldContain "TOrder-0001" }
            } finally {
                clients.forEach(StatusClientSocket::close)
                refused.close()
            }
        }
    }
})

/** Everything the channel sends until it closes the connection (at most 10 s). */
private suspend fun answerOf(socket: Socket): String = withContext(Dispatchers.IO) {
    socket.soTimeout = 10_000
    runCatching { socket.getInputStream().readNBytes(1_000).decodeToString() }.getOrDefault("")
}
