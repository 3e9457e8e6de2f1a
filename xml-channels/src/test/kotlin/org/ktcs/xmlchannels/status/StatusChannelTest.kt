package org.ktcs.xmlchannels.status

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.withTimeout
import org.ktcs.api.event.TransportOrderEvent
import org.ktcs.api.event.VehicleEvent
import org.ktcs.api.model.Position
import org.ktcs.api.model.ProcState
import org.ktcs.api.model.Vehicle
import org.ktcs.api.model.VehicleState
import org.ktcs.api.order.Destination
import org.ktcs.api.order.TransportOrderCreation
import org.ktcs.api.order.TransportOrderState
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.HostSchemas
import org.ktcs.xmlchannels.HostSchemas.validate
import org.ktcs.xmlchannels.XmlChannels
import org.ktcs.xmlchannels.XmlTree
import org.ktcs.xmlchannels.sample
import org.ktcs.xmlchannels.toOrder
import org.ktcs.xmlchannels.withChannels

class StatusChannelTest : FunSpec({
    val order = TransportOrderCreation(
        name = "TOrder-0001",
        destinations = listOf(Destination("Storage 01", "Load cargo"), Destination("Storage 02", "Unload cargo")),
        properties = mapOf("waitBefore" to "Unload"),
    ).toOrder("TOrder-0001")
    val vehicle = Vehicle("Vehicle-01", state = VehicleState.IDLE)

    test("an order change gets the documented order status message, followed by the separator") {
        val services = FakeKernelServices()
        val message = withStatusClients(services, 1) { channels, (client) ->
            services.events.emit(TransportOrderEvent(order, order.copy(state = TransportOrderState.ACTIVE)))
            client.next()!!
        }

        HostSchemas.status.validate(message)
        XmlTree.of(message) shouldBe XmlTree.of(sample("xml-telegram-status.xml"))
    }

    test("a vehicle change gets a vehicle status message with position, state, processing state and order") {
        val services = FakeKernelServices()
        val moved = vehicle.copy(
            currentPosition = "Point-0001",
            precisePosition = Position(100, 110, 120),
            state = VehicleState.EXECUTING,
            procState = ProcState.PROCESSING_ORDER,
            transportOrder = "TOrder-0001",
        )
        val message = withStatusClients(services, 1) { _, (client) ->
            services.events.emit(VehicleEvent(vehicle, moved))
            client.next()!!
        }

        HostSchemas.status.validate(message)
        XmlTree.of(message).children.single() shouldBe XmlTree(
            "statusMessage",
            sortedMapOf(
                "xsi:type" to "vehicleStatusMessage",
                "vehicleName" to "Vehicle-01",
                "position" to "Point-0001",
                "state" to "EXECUTING",
                "processingState" to "PROCESSING_ORDER",
                "transportOrderName" to "TOrder-0001",
            ),
            listOf(XmlTree("precisePosition", sortedMapOf("x" to "100", "y" to "110", "z" to "120"), emptyList())),
        )
    }

    test("changes a host can't see, like the energy level, send nothing; every client gets every message") {
        val services = FakeKernelServices()
        val messages = withStatusClients(services, 2) { _, clients ->
            services.events.emit(VehicleEvent(vehicle, vehicle.copy(energyLevel = 42)))
            services.events.emit(VehicleEvent(vehicle, vehicle.copy(state = VehicleState.CHARGING)))
            clients.map { it.next()!! }
        }

        messages.forEach { it shouldContain "state=\"CHARGING\"" }
    }

    test("a separator inside a value is escaped, so that hosts can split the stream at every separator") {
        val services = FakeKernelServices()
        val message = withStatusClients(services, 1) { _, (client) ->
            services.events.emit(TransportOrderEvent(null, order.copy(properties = mapOf("route" to "A|B"))))
            client.next()!!
        }

        HostSchemas.status.validate(message)
        XmlTree.of(message).children.single().children.last().attributes["value"] shouldBe "A|B"
    }

    test("what a client sends is ignored") {
        val services = FakeKernelServices()
        val message = withStatusClients(services, 1) { _, (client) ->
            client.socket.getOutputStream().apply {
                write("<hello/>\r\n\r\n".toByteArray())
                flush()
            }
            services.events.emit(TransportOrderEvent(null, order))
            client.next()!!
        }

        message shouldContain "orderState=\"RAW\""
    }

    test("the channel follows the kernel's events only while a status client is connected") {
        val services = FakeKernelServices()
        withChannels(services) { channels ->
            repeat(2) {
                val client = StatusClientSocket(channels.statusPort)
                withTimeout(5_000) { channels.statusClients.first { it == 1 } }
                services.events.subscriptionCount.value shouldBe 1
                services.events.emit(TransportOrderEvent(null, order))
                client.next()!! shouldContain "orderState=\"RAW\""
                client.close()
                // With nobody connected, no thread is woken for every kernel event.
                withTimeout(5_000) { services.events.subscriptionCount.first { it == 0 } }
                channels.statusClients.value shouldBe 0
            }
        }
    }
})

/** Runs [block] once [count] status clients are connected and the channel listens to the kernel's events. */
suspend fun <T> withStatusClients(
    services: FakeKernelServices,
    count: Int,
    block: suspend (XmlChannels, List<StatusClientSocket>) -> T,
): T = withChannels(services) { channels ->
    val clients = List(count) { StatusClientSocket(channels.statusPort) }
    try {
        withTimeout(5_000) {
            services.events.subscriptionCount.first { it > 0 }
            channels.statusClients.first { it == count }
        }
        block(channels, clients)
    } finally {
        clients.forEach(StatusClientSocket::close)
    }
}
