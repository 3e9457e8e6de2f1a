package org.ktcs.xmlchannels.status

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.ints.shouldBeLessThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeout
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.XmlChannels
import org.ktcs.xmlchannels.capturingWarnings
import org.ktcs.xmlchannels.toOrder
import org.ktcs.xmlchannels.withChannels

class SlowStatusClientTest : FunSpec({
    test("a client that does not read is dropped once its queue is full; the others get every message") {
        val services = FakeKernelServices()
        val (_, warnings) = capturingWarnings(StatusChannelServer::class.java) {
            withChannels(services) { channels ->
                StatusClientSocket(channels.statusPort, receiveBuffer = 4096).use { slow ->
                    StatusClientSocket(channels.statusPort).use { fast ->
                        awaitClients(services, channels, 2)
                        val sent = emitUntilDropped(services, channels, fast)
                        countAll(slow) shouldBeLessThan sent
                    }
                }
            }
        }

        warnings.single() shouldContain "dropped /127.0.0.1:"
    }
})

/**
 * Emits big orders in step with [fast] until a client is dropped, checks that [fast] got each of them, and returns
 * how many were sent. Big messages fill the slow client's socket buffers and then its queue quickly.
 */
private suspend fun emitUntilDropped(services: FakeKernelServices, channels: XmlChannels, fast: StatusClientSocket) =
    coroutineScope {
        val fastReceived = MutableStateFlow(0)
        val reader = launch { while (fast.next() != null) fastReceived.update { it + 1 } }
        var sent = 0
        while (sent < MAX_EVENTS && channels.statusClients.value == 2) {
            services.events.emit(bigEvent(++sent))
            withTimeout(5_000) { fastReceived.first { it == sent } }
        }
        withTimeout(5_000) { channels.statusClients.first { it == 1 } }
        fast.close()
        reader.join()
        fastReceived.value shouldBe sent
        sent
    }

private const val MAX_EVENTS = 2000

private suspend fun awaitClients(services: FakeKernelServices, channels: XmlChannels, count: Int) = withTimeout(5_000) {
    services.events.subscriptionCount.first { it > 0 }
    channels.statusClients.first { it == count }
}

private fun bigEvent(index: Int): TransportOrderEvent {
    val payload = mapOf("payload" to "x".repeat(64 * 1024))
    val creation = TransportOrderCreation("big", listOf(Destination("Storage 01", "NOP")), properties = payload)
    return TransportOrderEvent(null, creation.toOrder("TOrder-$index"))
}

/** Messages read up to the end of the connection. */
private suspend fun countAll(client: StatusClientSocket): Int {
    var count = 0
    while (client.next() != null) count++
    return count
}
