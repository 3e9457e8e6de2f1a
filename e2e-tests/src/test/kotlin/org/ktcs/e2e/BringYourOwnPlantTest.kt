package org.ktcs.e2e

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import java.net.Socket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path

/**
 * A new user's first contact: unmodified openTCS plant files (whose vehicles have no position) and a plant where no
 * vehicle has one. Without any manual step, an order sent over the web API and one sent over the XML channel finish.
 */
class BringYourOwnPlantTest : FunSpec({
    val fixtures = RepositoryRoot.path.resolve("kernel/src/test/resources/fixtures/opentcs/plant-models")

    fun unplacedDemo(): Path {
        val demo = RepositoryRoot.path.resolve("kernel/src/main/resources/org/ktcs/kernel/demo/ktcs-demo.xml")
        val text = Files.readString(demo).replace(Regex("""\s*<property name="loopback:initialPosition"[^>]*/>"""), "")
        text.contains("initialPosition") shouldBe false
        return Files.writeString(tempdir().toPath().resolve("unplaced.xml"), text)
    }

    fun runsOrders(model: Path) {
        val settings = listOf(
            "web.bindAddress=127.0.0.1",
            "web.port=0",
            "xml.bindAddress=127.0.0.1",
            "xml.orders.port=0",
            "xml.status.port=0",
            "loopback.timeFactor=20",
        ).flatMap { listOf("--set", it) }
        KtcsProcess("--model", model.toString(), *settings.toTypedArray()).use { ktcs ->
            val ports = Regex("orders on port (\\d+), status on port (\\d+)").find(ktcs.awaitLine("XML channels:"))!!
            val base = Regex("web API (http://\\S+)/v1").find(ktcs.awaitLine("kTCS ready"))!!.groupValues[1]
            ktcs.output() shouldContain "had no position; placed it on the free"
            Socket("127.0.0.1", ports.groupValues[2].toInt()).use { status ->
                val http = HttpClient.newHttpClient()
                val body = """{"destinations":[{"locationName":"Storage 01","operation":"Load cargo"},
                    {"locationName":"Goods out 01","operation":"Unload cargo"}]}"""
                val created = http.send(
                    HttpRequest.newBuilder(URI("$base/v1/transportOrders/Web-1"))
                        .header("Content-Type", "application/json")
                        .POST(HttpRequest.BodyPublishers.ofString(body)).build(),
                    HttpResponse.BodyHandlers.ofString(),
                )
                created.statusCode() shouldBe 200
                val receipt = Socket("127.0.0.1", ports.groupValues[1].toInt()).use { orders ->
                    orders.getOutputStream().write(TELEGRAM.toByteArray())
                    orders.shutdownOutput()
                    orders.getInputStream().readBytes().decodeToString()
                }
                val xmlOrder = Regex("orderName=\"([^\"]+)\"").find(receipt)!!.groupValues[1]
                status.finishedOrders(setOf(xmlOrder, "Web-1")) shouldBe setOf(xmlOrder, "Web-1")
            }
            ktcs.terminate() shouldBe 0
        }
    }

    test("openTCS 5.0's Demo-01, unchanged") { runsOrders(fixtures.resolve("opentcs-5.0/Demo-01.xml")) }

    test("openTCS 7.5's Demo-01, unchanged") { runsOrders(fixtures.resolve("opentcs-7.5-head/Demo-01.xml")) }

    test("a plant where no vehicle has a position") { runsOrders(unplacedDemo()) }
})

private val TELEGRAM = """
    <?xml version="1.0" encoding="UTF-8"?>
    <tcsOrderSet>
        <order xsi:type="transport" id="A" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
            <destination locationName="Goods in north 01" operation="Load cargo"/>
            <destination locationName="Storage 02" operation="Unload cargo"/>
        </order>
    </tcsOrderSet>
""".trimIndent()
