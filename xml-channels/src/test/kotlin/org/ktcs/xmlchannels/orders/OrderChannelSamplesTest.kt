package org.ktcs.xmlchannels.orders

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainExactly
import io.kotest.matchers.shouldBe
import org.ktcs.api.order.Destination
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.HostClient
import org.ktcs.xmlchannels.HostSchemas
import org.ktcs.xmlchannels.HostSchemas.validate
import org.ktcs.xmlchannels.XmlTree
import org.ktcs.xmlchannels.sample
import org.ktcs.xmlchannels.testSettings
import org.ktcs.xmlchannels.withChannels
import java.nio.file.Files
import java.time.Instant

/** openTCS's documented telegrams get openTCS's documented receipts (kTCS's order names aside). */
class OrderChannelSamplesTest : FunSpec({
    test("the sample telegrams and scripts are valid by the module's schemas") {
        HostSchemas.order.validate(sample("xml-telegram-two-orders.xml"))
        HostSchemas.order.validate(sample("xml-telegram-batch.xml"))
        HostSchemas.orderScript.validate(sample("test.tcs"))
        HostSchemas.orderScript.validate(sample("template.tcs"))
        HostSchemas.response.validate(sample("xml-telegram-receipt-orders.xml"))
        HostSchemas.response.validate(sample("xml-telegram-receipt-batch.xml"))
    }

    test("the two-order telegram creates both orders and gets the documented receipt") {
        val services = FakeKernelServices()
        val receipt = withChannels(services) { HostClient.send(it.ordersPort, sample("xml-telegram-two-orders.xml")) }

        HostSchemas.response.validate(receipt)
        receipt.tree() shouldBe sample("xml-telegram-receipt-orders.xml").tree()
        services.created.map { it.name } shouldBe listOf("TOrder-0001", "TOrder-0002")
    }

    test("destinations, deadline, intended vehicle and properties reach the kernel") {
        val services = FakeKernelServices()
        withChannels(services) { HostClient.send(it.ordersPort, sample("xml-telegram-two-orders.xml")) }

        val (first, second) = services.created
        first.deadline shouldBe Instant.parse("2016-11-24T10:18:39.124Z")
        first.intendedVehicle shouldBe "Vehicle-01"
        first.properties shouldBe mapOf("waitBefore" to "Unload")
        first.driveOrders.map { it.destination } shouldContainExactly listOf(
            Destination("Storage 01", "Load cargo"),
            Destination("Storage 02", "Unoad cargo"),
        )
        second.deadline shouldBe Instant.MAX
        second.driveOrders.map { it.destination.properties } shouldBe
            listOf(mapOf("drillSize" to "3"), mapOf("drillSize" to "8"), emptyMap())
    }

    test("the batch telegram runs test.tcs and gets the documented receipt") {
        val settings = testSettings()
        Files.writeString(settings.scriptsDirectory.resolve("test.tcs"), sample("test.tcs"))
        val services = FakeKernelServices()
        val receipt =
            withChannels(services, settings) { HostClient.send(it.ordersPort, sample("xml-telegram-batch.xml")) }

        HostSchemas.response.validate(receipt)
        receipt.tree() shouldBe sample("xml-telegram-receipt-batch.xml").tree()
        services.created.map { order -> order.driveOrders.map { it.destination.target } } shouldBe
            listOf(listOf("TST11", "TST8"), listOf("TST12", "TST9"))
    }
})

private fun String.tree() = XmlTree.of(this, ignored = setOf("orderName"))
