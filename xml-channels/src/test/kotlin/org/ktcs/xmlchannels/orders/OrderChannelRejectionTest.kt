package org.ktcs.xmlchannels.orders

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import org.ktcs.xmlchannels.FakeKernelServices
import org.ktcs.xmlchannels.HostClient
import org.ktcs.xmlchannels.XmlChannels
import org.ktcs.xmlchannels.capturingWarnings
import org.ktcs.xmlchannels.sample
import org.ktcs.xmlchannels.testSettings
import org.ktcs.xmlchannels.withChannels

/**
 * A telegram that is too long, too slow, not XML or not an order set creates nothing: the connection is closed
 * without a receipt, and one warning names the client and the reason.
 */
class OrderChannelRejectionTest : FunSpec({
    val telegram = sample("xml-telegram-two-orders.xml")

    suspend fun rejected(expectedReason: String, send: suspend (XmlChannels) -> String) {
        val services = FakeKernelServices()
        val (answer, warnings) = capturingWarnings(OrderChannelServer::class.java) {
            withChannels(services, block = send)
        }

        answer shouldBe ""
        services.created.shouldBeEmpty()
        warnings shouldHaveSize 1
        warnings.single() shouldContain "/127.0.0.1:"
        warnings.single() shouldContain expectedReason
    }

    test("a telegram over the input limit") {
        val padding = "<!-- ${"x".repeat(100 * 1024)} -->"
        rejected("longer than 102400 bytes") { HostClient.send(it.ordersPort, telegram + padding) }
    }

    test("malformed XML") {
        rejected("malformed XML") { HostClient.send(it.ordersPort, telegram.replace("</tcsOrderSet>", "")) }
    }

    test("an empty telegram") {
        rejected("malformed XML") { HostClient.send(it.ordersPort, "") }
    }

    test("a document that is not a tcsOrderSet") {
        rejected("root element is 'tcsScriptFile'") { HostClient.send(it.ordersPort, sample("test.tcs")) }
    }

    test("an order without an id") {
        rejected("not a valid tcsOrderSet: missing or bad value at /order[2]/id") {
            HostClient.send(it.ordersPort, telegram.replace("id=\"TransportOrder-02\"", ""))
        }
    }

    test("a client that stops sending before the telegram ends") {
        rejected("telegram not complete within") { channels ->
            withContext(Dispatchers.IO) {
                HostClient.connect(channels.ordersPort).use { socket ->
                    socket.getOutputStream().write(telegram.take(100).toByteArray())
                    socket.getInputStream().readBytes().decodeToString()
                }
            }
        }
    }

    test("a DOCTYPE, which could smuggle in external entities") {
        val doctype = """<!DOCTYPE tcsOrderSet [<!ENTITY x SYSTEM "file:///etc/passwd">]>"""
        rejected("malformed") {
            HostClient.send(it.ordersPort, "<?xml version=\"1.0\"?>$doctype<tcsOrderSet>&x;</tcsOrderSet>")
        }
    }
})
