package org.ktcs.adapters.vda5050

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.ktcs.adapters.vda5050.mqtt.BrokerEndpoint
import org.ktcs.adapters.vda5050.mqtt.MqttLink
import org.ktcs.adapters.vda5050.protocol.InstantActions
import org.ktcs.adapters.vda5050.protocol.Order
import org.ktcs.adapters.vda5050.protocol.Vda5050Json
import org.ktcs.adapters.vda5050.sim.SimulatedVehicle
import org.ktcs.adapters.vda5050.sim.SimulatedVehicleSpec
import org.ktcs.kernel.app.KernelApplication
import org.ktcs.kernel.app.LoadedModel
import org.ktcs.kernel.app.PlantModelLoader
import org.ktcs.kernel.config.ConfigLoader
import java.net.ServerSocket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import java.util.Collections
import java.util.concurrent.Executors

/** A free TCP port on the loopback interface (never 1883). */
fun freePort(): Int = ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress()).use { it.localPort }

/** The demo plant whose first [count] vehicles are VDA 5050 vehicles standing on [starts]; the others are gone. */
fun vdaDemo(starts: List<String>, extra: Map<String, String> = emptyMap()): LoadedModel {
    val demo = PlantModelLoader.loadDemo()
    val vehicles = demo.model.vehicles.take(starts.size).mapIndexed { i, vehicle ->
        vehicle.copy(properties = vdaProperties("SIM-${i + 1}") + extra)
    }
    return demo.copy(model = demo.model.copy(vehicles = vehicles))
}

/** kTCS's configuration for a test: web API on a free loopback port, data in a temporary directory, and [settings]. */
fun testConfig(vararg settings: String) = ConfigLoader().load(
    null,
    emptyMap(),
    listOf(
        "web.port=0",
        "web.bindAddress=127.0.0.1",
        "kernel.dataDirectory=${Files.createTempDirectory(Path.of("target").toAbsolutePath(), "ktcs-vda-test")}",
        "persistence.durability=OFF",
    ) + settings,
)

fun vdaProperties(serial: String) = mapOf(
    "vda5050:version" to "2.0",
    "vda5050:interfaceName" to "uagv",
    "vda5050:manufacturer" to "kTCS",
    "vda5050:serialNumber" to serial,
)

/**
 * kTCS in-process with the VDA 5050 extension, its broker (embedded, or [brokerUrl]), simulated vehicles on the
 * given start points, and a spy client that records the orders and instant actions kTCS publishes.
 */
class VdaPlant(
    starts: List<String>,
    brokerUrl: String? = null,
    vehicleProperties: Map<String, String> = emptyMap(),
    private val timeFactor: Double = 8.0,
) : AutoCloseable {
    val brokerPort = if (brokerUrl == null) freePort() else URI(brokerUrl).port
    val endpoint = BrokerEndpoint("127.0.0.1", brokerPort, tls = false)
    private val model = vdaDemo(starts, vehicleProperties)
    private val config = testConfig(
        "dispatcher.parkIdleVehicles=false",
        "dispatcher.rechargeIdleVehicles=false",
        if (brokerUrl == null) "vda5050.embeddedBroker.port=$brokerPort" else "vda5050.brokerUrl=$brokerUrl",
        // `-Dktcs.test.embeddedBroker=hivemq` runs the VDA 5050 tests against the other embedded broker.
        "vda5050.embeddedBroker.implementation=${System.getProperty("ktcs.test.embeddedBroker", "builtin")}",
    )
    val application = KernelApplication(config, model, listOf(Vda5050Extension()))
    private val base = Regex("web API (http://\\S+)/v1").find(application.start())!!.groupValues[1]
    private val http = HttpClient.newHttpClient()
    private val executor = Executors.newSingleThreadScheduledExecutor {
        Thread(it, "vda-sim").apply { isDaemon = true }
    }
    val orders: MutableList<Order> = Collections.synchronizedList(mutableListOf())
    val instantActions: MutableList<InstantActions> = Collections.synchronizedList(mutableListOf())
    private val spy = MqttLink("spy-${System.nanoTime()}", endpoint).also { spy ->
        spy.connect()
        spy.subscribe("uagv/v2/kTCS/+/order", 1) {
            orders += Vda5050Json.decodeFromString(Order.serializer(), String(it))
        }
            .get()
        spy.subscribe("uagv/v2/kTCS/+/instantActions", 1) {
            instantActions += Vda5050Json.decodeFromString(InstantActions.serializer(), String(it))
        }.get()
    }
    val vehicles: List<SimulatedVehicle> = starts.mapIndexed { i, start -> simulated(i, start) }

    private val running = vehicles.toMutableList()

    /** Stops the [index]th simulated vehicle and plays it again from where it stands, connected to [endpoint]. */
    fun replaceVehicle(index: Int, endpoint: BrokerEndpoint): SimulatedVehicle {
        running[index].close()
        val at = vehicle(index)["currentPosition"]!!.jsonPrimitive.content
        return simulated(index, at, endpoint).also { running[index] = it }
    }

    fun vehicleName(index: Int): String = model.model.vehicles[index].name

    /** A simulated vehicle for the [index]th VDA vehicle, on point [start], started. */
    fun simulated(index: Int, start: String, endpoint: BrokerEndpoint = this.endpoint): SimulatedVehicle {
        val point = model.model.point(start)!!.pose.position
        val spec = SimulatedVehicleSpec(
            manufacturer = "kTCS",
            serialNumber = "SIM-${index + 1}",
            topicPrefix = "uagv/v2/kTCS/SIM-${index + 1}",
            startNode = start,
            startX = point.x / 1000.0,
            startY = point.y / 1000.0,
            speedMetresPerSecond = 2.0,
            actionMillis = 800,
            timeFactor = timeFactor,
        )
        return SimulatedVehicle(spec, endpoint, executor).also { it.start() }
    }

    fun publishRaw(topic: String, json: String) {
        spyLink().publish(topic, json.toByteArray(), 1).get()
    }

    private fun spyLink() = spy

    fun get(path: String): JsonObject = Json.parseToJsonElement(send("GET", path, null).second).jsonObject

    /** The vehicle's load handling devices as the kernel has them (the web API does not show them). */
    fun loadHandlingDevices(index: Int) =
        application.kernel.plant.model().vehicle(vehicleName(index))!!.loadHandlingDevices

    fun vehicle(index: Int): JsonObject = get("/vehicles/${vehicleName(index)}")

    fun orderState(name: String): String = get("/transportOrders/$name")["state"]!!.jsonPrimitive.content

    fun send(method: String, path: String, json: String?): Pair<Int, String> {
        val body = json?.let { HttpRequest.BodyPublishers.ofString(it) } ?: HttpRequest.BodyPublishers.noBody()
        val request = HttpRequest.newBuilder(URI("$base/v1$path")).method(method, body)
            .header("Content-Type", "application/json").build()
        val response = http.send(request, HttpResponse.BodyHandlers.ofString())
        return response.statusCode() to response.body()
    }

    fun post(path: String, json: String = "") {
        val (status, body) = send("POST", path, json)
        check(status == 200) { "POST $path: $status $body" }
    }

    fun put(path: String) {
        val (status, body) = send("PUT", path, null)
        check(status == 200) { "PUT $path: $status $body" }
    }

    /** Creates transport order [name] to [location] with [operation], for vehicle [vehicle] if given. */
    fun order(name: String, location: String, operation: String, vehicle: String? = null) {
        val intended = vehicle?.let { ""","intendedVehicle":"$it"""" } ?: ""
        post(
            "/transportOrders/$name",
            """{"destinations":[{"locationName":"$location","operation":"$operation"}]$intended}""",
        )
    }

    override fun close() {
        running.forEach { runCatching { it.close() } }
        runCatching { spy.close() }
        application.stop()
        executor.shutdownNow()
    }
}
