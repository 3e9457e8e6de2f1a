package org.ktcs.xmlchannels.reliability

import io.kotest.core.spec.style.FunSpec
import io.kotest.engine.spec.tempdir
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import org.ktcs.xmlchannels.HostClient
import org.ktcs.xmlchannels.XmlChannelsExtension
import org.ktcs.xmlchannels.errorsLoggedWhile
import org.ktcs.xmlchannels.status.StatusClientSocket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files

/**
 * Seeded fuzzing of the order channel against the real kernel and the demo plant (issue #14): valid telegrams,
 * mutated and truncated ones, random bytes, XML 1.1 control characters, DTDs and scripts outside the directory.
 * Every telegram gets a receipt or a clean close; only orders acknowledged as created exist; nothing is logged at
 * ERROR; both channels work afterwards.
 */
class TelegramFuzzTest : FunSpec({
    test("$CASES generated telegrams: no failure, nothing created by invalid input, both channels alive") {
        val scripts = tempdir("ktcs-fuzz-scripts").toPath()
        val config = ConfigLoader().load(
            null,
            emptyMap(),
            listOf(
                "web.bindAddress=127.0.0.1",
                "web.port=0",
                "xml.bindAddress=127.0.0.1",
                "xml.orders.port=0",
                "xml.status.port=0",
                "xml.scriptsDirectory=$scripts",
                "xml.orders.idleTimeout=2000",
            ),
        )
        val application = KernelApplication(config, PlantModelLoader.loadDemo(), listOf(XmlChannelsExtension())) {}
        val ready = application.start()
        val ordersPort = Regex("XML orders tcp://\\S+:(\\d+)").find(ready)!!.groupValues[1].toInt()
        val statusPort = Regex("XML status tcp://\\S+:(\\d+)").find(ready)!!.groupValues[1].toInt()
        val web = Regex("web API (http://\\S+/v1)").find(ready)!!.groupValues[1]
        try {
            val status = StatusClientSocket(statusPort)
            val generator = TelegramGenerator(SEED)
            var receipts = 0
            var closed = 0
            val acknowledged = mutableSetOf<String>()
            val errors = errorsLoggedWhile {
                repeat(CASES) {
                    val answer = HostClient.send(ordersPort, generator.next())
                    if (answer.contains("tcsResponseSet")) receipts++ else closed++
                    ACKNOWLEDGED.findAll(answer).forEach { acknowledged += it.groupValues[1] }
                }
            }
            val created = orderNames(web)
            val failures = errors.size + (created - acknowledged).size
            println(
                "xml fuzz (seed $SEED): cases tried $CASES, handled ${receipts + closed} " +
                    "(receipts $receipts, closed without receipt $closed), failures $failures, " +
                    "orders created ${created.size}",
            )
            errors.shouldBeEmpty()
            created shouldBe acknowledged

            // Both channels still work: a valid telegram is answered, and the status client hears of its order.
            val valid = """<tcsOrderSet><order xsi:type="transport" id="After" """ +
                """xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">""" +
                """<destination locationName="Storage 01" operation="Load cargo"/></order></tcsOrderSet>"""
            val receipt = HostClient.send(ordersPort, valid)
            receipt shouldContain "executionSuccessful=\"true\""
            val name = ACKNOWLEDGED.find(receipt)!!.groupValues[1]
            var message = ""
            while (!message.contains(name)) message = status.next() ?: error("the status channel closed")
            status.close()
        } finally {
            application.stop()
        }
    }
}) {
    companion object {
        const val SEED = 14L
        const val CASES = 1_100
        val ACKNOWLEDGED = Regex("executionSuccessful=\"true\" orderName=\"([^\"]+)\"")
    }
}

private fun orderNames(web: String): Set<String> {
    val body = HttpClient.newHttpClient().send(
        HttpRequest.newBuilder(URI("$web/transportOrders")).build(),
        HttpResponse.BodyHandlers.ofString(),
    ).body()
    return Regex("\"name\"\\s*:\\s*\"([^\"]+)\"").findAll(body).map { it.groupValues[1] }
        .filter { it.startsWith("TOrder-") }.toSet()
}
