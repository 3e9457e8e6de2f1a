package org.ktcs.e2e

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldHaveSize
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import java.net.Socket

/** A host system talks to `./ktcs` over the XML channels while four loopback vehicles drive. */
class XmlChannelsEndToEndTest : FunSpec({
    test("orders sent as a telegram get a receipt and reach FINISHED on the status channel") {
        val settings = listOf(
            "web.bindAddress=127.0.0.1",
            "web.port=0",
            "xml.bindAddress=127.0.0.1",
            "xml.orders.port=0",
            "xml.status.port=0",
            "loopback.timeFactor=20",
        ).flatMap { listOf("--set", it) }
        KtcsProcess(*settings.toTypedArray()).use { ktcs ->
            val ports = Regex(
                "orders on port (\\d+), status on port (\\d+)",
            ).find(ktcs.awaitLine("XML channels:"))!!.groupValues
            ktcs.awaitLine("kTCS ready")
            Socket("127.0.0.1", ports[2].toInt()).use { status ->
                val receipt = Socket("127.0.0.1", ports[1].toInt()).use { orders ->
                    orders.getOutputStream().write(TELEGRAM.toByteArray())
                    orders.shutdownOutput()
                    orders.getInputStream().readBytes().decodeToString()
                }
                receipt shouldContain "id=\"A\""
                receipt shouldContain "id=\"B\""
                val names = Regex("orderName=\"(TOrder-[^\"]+)\"").findAll(receipt).map { it.groupValues[1] }.toList()
                names shouldHaveSize 2

                status.finishedOrders(names.toSet()) shouldBe names.toSet()
            }
            ktcs.terminate() shouldBe 0
        }
    }
})

private val TELEGRAM = """
    <?xml version="1.0" encoding="UTF-8"?>
    <tcsOrderSet>
        <order xsi:type="transport" id="A" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
            <destination locationName="Storage 01" operation="Load cargo"/>
            <destination locationName="Goods out 01" operation="Unload cargo"/>
        </order>
        <order xsi:type="transport" id="B" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
            <destination locationName="Goods in north 01" operation="Load cargo"/>
            <destination locationName="Storage 02" operation="Unload cargo"/>
        </order>
    </tcsOrderSet>
""".trimIndent()
