package org.ktcs.xmlchannels.orders

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactlyInAnyOrder
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldStartWith
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.HostClient
import org.ktcs.xmlchannels.HostSchemas
import org.ktcs.xmlchannels.HostSchemas.validate
import org.ktcs.xmlchannels.XmlTree
import org.ktcs.xmlchannels.withChannels

class OrderChannelTest : FunSpec({
    test("a telegram ended by an empty line is answered while the client keeps its side open") {
        val services = FakeKernelServices()
        val receipt =
            withChannels(services) { HostClient.send(it.ordersPort, orderSet(transport("a")), crlfEnd = true) }

        HostSchemas.response.validate(receipt)
        receipt.responses() shouldBe listOf(response("a", "TOrder-0001"))
        services.created.size shouldBe 1
    }

    test("orders the kernel refuses fail with its reason, and the others are created") {
        val services = FakeKernelServices()
        val telegram = orderSet(
            transport("good"),
            transport("bad-location", location = "Nowhere"),
            transport("bad-vehicle", attributes = """intendedVehicle="Vehicle-99""""),
            transport("bad-deadline", attributes = """deadline="tomorrow""""),
            """<order xsi:type="teleport" id="bad-type" xmlns:xsi="$XSI"/>""",
            transport("good-too", body = "<dependency>TOrder-0001</dependency>"),
        )
        val receipt = withChannels(services) { HostClient.send(it.ordersPort, telegram) }

        HostSchemas.response.validate(receipt)
        receipt.responses() shouldBe listOf(
            response("good", "TOrder-0001"),
            failure("bad-location", "unknown location 'Nowhere'"),
            failure("bad-vehicle", "unknown vehicle 'Vehicle-99'"),
            failure("bad-deadline", "deadline 'tomorrow' is not an xsd:dateTime"),
            failure("bad-type", "unknown order type 'teleport'"),
            response("good-too", "TOrder-0002"),
        )
        services.created.map { it.name } shouldBe listOf("TOrder-0001", "TOrder-0002")
        services.created.last().dependencies shouldBe setOf("TOrder-0001")
    }

    test("an empty order set gets an empty receipt") {
        val receipt = withChannels { HostClient.send(it.ordersPort, orderSet()) }

        HostSchemas.response.validate(receipt)
        receipt.responses() shouldBe emptyList()
    }

    test("50 clients at once each get the receipt for their own order") {
        val services = FakeKernelServices()
        HostSchemas.order.validate(orderSet(transport("client-1")))
        val receipts = withChannels(services) { channels ->
            coroutineScope {
                (1..50).map { async { HostClient.send(channels.ordersPort, orderSet(transport("client-$it"))) } }
                    .awaitAll()
            }
        }

        receipts.forEach { HostSchemas.response.validate(it) }
        receipts.map { it.responses().single().attributes["id"] } shouldContainExactlyInAnyOrder
            (1..50).map { "client-$it" }
        receipts.map { it.responses().single().attributes["orderName"] }.toSet().size shouldBe 50
        services.created.size shouldBe 50
    }

    test("the receipt starts with openTCS's XML declaration") {
        withChannels { HostClient.send(it.ordersPort, orderSet()) } shouldStartWith
            """<?xml version="1.0" encoding="UTF-8" standalone="yes"?>"""
    }
})
