package org.ktcs.e2e.plant

import io.kotest.assertions.withClue
import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldBeEmpty
import io.kotest.matchers.collections.shouldContain
import io.kotest.matchers.ints.shouldBeGreaterThan
import io.kotest.matchers.shouldBe
import io.kotest.matchers.string.shouldContain
import org.ktcs.api.model.PlantModel
import org.ktcs.e2e.KtcsProcess
import org.ktcs.examples.tcpdriver.LineVehicleSimulator
import org.ktcs.examples.tcpdriver.TcpVehicleDriverFactory
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.persistence.PlantModelFiles
import java.net.Socket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.concurrent.thread
import kotlin.time.Duration.Companion.seconds

/**
 * The packaged application (`./ktcs`) with the demo plant, its four loopback vehicles and a fifth vehicle driven by
 * the example TCP driver, loaded from a jar in the extensions directory, whose vehicle the example's simulator
 * plays; the example overview panel and theme come from a second jar there. At the same time: orders over REST,
 * orders as XML telegrams, an order from the browser overview's dialog (in headless Chromium, left out with the
 * reason printed where Chromium is missing), the WebSocket and the XML status channel followed. Every order
 * finishes, no resource is ever held by two vehicles, the TCP vehicle does its share and nothing is logged as an
 * error.
 */
class WholePlantEndToEndTest : FunSpec({
    test("REST, XML and browser orders all finish on a plant with extension jars, without double allocations") {
        val directory = Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-whole-plant")
        val extensions = Files.createDirectories(directory.resolve("extensions"))
        Files.copy(ExampleJars.tcpVehicleDriver, extensions.resolve("ktcs-example-tcp-vehicle-driver.jar"))
        Files.copy(ExampleJars.overviewPanelTheme, extensions.resolve("ktcs-example-overview-panel-theme.jar"))
        LineVehicleSimulator("Point-0027", travelMillis = 150, operationMillis = 300).use { simulator ->
            val model = modelWithTcpVehicle(simulator.port)
            val modelFile = directory.resolve("plant.xml").also { PlantModelFiles.write(model, it) }
            KtcsProcess(*arguments(modelFile, extensions)).use { ktcs ->
                val ready = ktcs.awaitLine("kTCS ready")
                ready shouldContain "tcp-vehicle-driver (from $extensions/ktcs-example-tcp-vehicle-driver.jar)"
                ready shouldContain "overview-examples (from $extensions/ktcs-example-overview-panel-theme.jar)"
                val web = Regex("web API (http://\\S+)/v1").find(ready)!!.groupValues[1]
                val xmlOrders = Regex("XML orders tcp://\\S+:(\\d+)").find(ready)!!.groupValues[1].toInt()
                val xmlStatus = Regex("XML status tcp://\\S+:(\\d+)").find(ready)!!.groupValues[1].toInt()

                PlantFollower(web).use { follower ->
                    follower.awaitSnapshots()
                    val orders = CopyOnWriteArrayList<String>()
                    val status = StatusChannelFollower(xmlStatus)
                    val activities = listOfNotNull(
                        activity("REST orders") { orders += RestOrders(web).createAll() },
                        activity("XML telegram") { orders += sendXmlTelegram(xmlOrders) },
                        browserActivity(web, model) { orders += it },
                    )
                    activities.forEach { it.join() }
                    activities.flatMap { it.failures }.shouldBeEmpty()

                    awaitAllFinal(follower, orders)
                    withClue(orders.associateWith { follower.stateOf(it) }.toString()) {
                        orders.map { follower.stateOf(it) }.toSet() shouldBe setOf("FINISHED")
                    }
                    follower.doubleAllocations.shouldBeEmpty()
                    follower.errors.shouldBeEmpty()
                    orders.mapNotNull { follower.processorOf(it) } shouldContain "Tcp-01"
                    simulator.executed shouldBeGreaterThan 0
                    status.finishedOrders(orders.filter { it.startsWith("TOrder-") }.toSet())
                    println(
                        "whole plant: ${orders.size} orders finished, ${follower.eventCount} WebSocket events, " +
                            "Tcp-01 carried out ${simulator.executed} commands",
                    )
                }
                ktcs.terminate() shouldBe 0
                withClue("kTCS logged errors") {
                    ktcs.output().lines().filter { ERROR_LINE.containsMatchIn(it) }.shouldBeEmpty()
                }
            }
        }
    }
})

/** The browser overview as an order source, or nothing (with the reason printed) where Chromium is missing. */
private fun browserActivity(web: String, model: PlantModel, onOrderCreated: (String) -> Unit): Activity? {
    val skipReason = Chromium.skipReason()
    if (skipReason != null) {
        println("whole plant: browser overview left out: $skipReason")
        return null
    }
    return activity("browser overview") { BrowserOverview(web, model).visit(onOrderCreated) }
}

private val ERROR_LINE = Regex("""\sERROR\s""")

private fun arguments(model: Path, extensions: Path): Array<String> = (
    listOf("--model", model.toString()) +
        listOf(
            "web.bindAddress=127.0.0.1",
            "web.port=0",
            "xml.bindAddress=127.0.0.1",
            "xml.orders.port=0",
            "xml.status.port=0",
            "loopback.timeFactor=10",
            "overview.vehicleTheme=energy",
            "extensions.directory=$extensions",
        ).flatMap { listOf("--set", it) }
    ).toTypedArray()

/** The demo plant plus the vehicle "Tcp-01", driven by the example TCP driver, its vehicle listening on [port]. */
private fun modelWithTcpVehicle(port: Int): PlantModel {
    val demo = PlantModelLoader.loadDemo().model
    val tcpVehicle = demo.vehicles.first().copy(
        name = "Tcp-01",
        properties = mapOf(
            "tcs:preferredAdapterClass" to TcpVehicleDriverFactory.NAME,
            TcpVehicleDriverFactory.PORT to port.toString(),
        ),
    )
    return demo.copy(vehicles = demo.vehicles + tcpVehicle)
}

private fun awaitAllFinal(follower: PlantFollower, orders: List<String>) {
    val deadline = System.nanoTime() + 75.seconds.inWholeNanoseconds
    val finalStates = setOf("FINISHED", "FAILED", "UNROUTABLE")
    while (System.nanoTime() < deadline && !orders.all { follower.stateOf(it) in finalStates }) Thread.sleep(200)
}

/** Something the test does at the same time as the others; its failures are kept for the assertion. */
private class Activity(val name: String, body: () -> Unit) {
    val failures = CopyOnWriteArrayList<String>()
    private val worker = thread(name = "activity-$name") {
        try {
            body()
        } catch (error: Throwable) {
            failures += "$name: $error"
        }
    }

    /** Waits for the activity to end; one still running after 60 s counts as failed, lest its checks go unseen. */
    fun join() {
        worker.join(60_000)
        if (worker.isAlive) failures += "$name: still running after 60 s"
    }
}

private fun activity(name: String, body: () -> Unit) = Activity(name, body)

/** Creates orders over the web API, one every few hundred milliseconds; two are meant for the TCP vehicle. */
private class RestOrders(private val web: String) {
    private val http = HttpClient.newHttpClient()

    fun createAll(): List<String> = ORDERS.mapIndexed { index, (from, to, vehicle) ->
        val name = "Rest-${index + 1}"
        val intended = vehicle?.let { ""","intendedVehicle":"$it"""" }.orEmpty()
        val body = """{"destinations":[{"locationName":"$from","operation":"Load cargo"},""" +
            """{"locationName":"$to","operation":"Unload cargo"}]$intended}"""
        val request = HttpRequest.newBuilder(URI("$web/v1/transportOrders/$name"))
            .header("Content-Type", "application/json")
            .POST(HttpRequest.BodyPublishers.ofString(body)).build()
        val response = http.send(request, HttpResponse.BodyHandlers.ofString())
        check(response.statusCode() == 200) { "creating $name: ${response.statusCode()} ${response.body()}" }
        Thread.sleep(300)
        name
    }

    private companion object {
        val ORDERS = listOf(
            Triple("Storage 01", "Goods out 01", null),
            Triple("Goods in north 01", "Storage 02", "Tcp-01"),
            Triple("Goods in south 01", "Goods out 02", null),
            Triple("Storage 02", "Goods out 01", null),
            Triple("Goods in north 02", "Storage 01", null),
            Triple("Goods in south 02", "Goods out 02", "Tcp-01"),
        )
    }
}

/** Sends one telegram with two orders to the XML order channel and returns the names kTCS gave them. */
private fun sendXmlTelegram(port: Int): List<String> {
    val receipt = Socket("127.0.0.1", port).use { socket ->
        socket.getOutputStream().write(TELEGRAM.toByteArray())
        socket.shutdownOutput()
        socket.getInputStream().readBytes().decodeToString()
    }
    val names = Regex("orderName=\"(TOrder-[^\"]+)\"").findAll(receipt).map { it.groupValues[1] }.toList()
    check(names.size == 2) { "the XML receipt names ${names.size} orders instead of 2: $receipt" }
    return names
}

/** Reads the XML status channel from the start; checks at the end that it reported the XML orders FINISHED. */
private class StatusChannelFollower(port: Int) {
    private val text = StringBuffer()
    private val socket = Socket("127.0.0.1", port)
    private val reader = thread(name = "xml-status", isDaemon = true) {
        runCatching {
            val input = socket.getInputStream().bufferedReader()
            val chunk = CharArray(8192)
            while (true) {
                val read = input.read(chunk)
                if (read < 0) break
                text.append(chunk, 0, read)
            }
        }
    }

    fun finishedOrders(expected: Set<String>) {
        val deadline = System.nanoTime() + 10.seconds.inWholeNanoseconds
        var finished = emptySet<String>()
        while (System.nanoTime() < deadline && !finished.containsAll(expected)) {
            finished = Regex("orderName=\"(TOrder-[^\"]+)\" orderState=\"FINISHED\"").findAll(text)
                .map { it.groupValues[1] }.toSet()
            Thread.sleep(100)
        }
        socket.close()
        reader.join(1_000)
        withClue("the XML status channel reported FINISHED for $finished") {
            finished.containsAll(expected) shouldBe
                true
        }
    }
}

private val TELEGRAM = """
    <?xml version="1.0" encoding="UTF-8"?>
    <tcsOrderSet>
        <order xsi:type="transport" id="A" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
            <destination locationName="Storage 01" operation="Load cargo"/>
            <destination locationName="Goods out 02" operation="Unload cargo"/>
        </order>
        <order xsi:type="transport" id="B" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
            <destination locationName="Goods in north 01" operation="Load cargo"/>
            <destination locationName="Storage 02" operation="Unload cargo"/>
        </order>
    </tcsOrderSet>
""".trimIndent()
